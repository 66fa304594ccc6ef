#!/usr/bin/env python3
"""Seeded fBm terrain by midpoint displacement (diamond-square) as a 16-bit PGM, for the
terrainlod build benchmark: terrain_fbm.py K AMPLITUDE OUT.pgm gives (2^K + 1)^2 samples."""
import random, struct, sys
k = int(sys.argv[1]); n = (1 << k) + 1; amp = float(sys.argv[2])
random.seed(7)
h = [0.0] * (n * n)
u = lambda: random.uniform(-1, 1)
for (i, j) in ((0, 0), (n - 1, 0), (0, n - 1), (n - 1, n - 1)): h[j * n + i] = amp * u()
step, scale = n - 1, amp
while step > 1:
    half = step // 2
    for j in range(half, n, step):
        for i in range(half, n, step):
            h[j*n+i] = 0.25*(h[(j-half)*n+i-half]+h[(j-half)*n+i+half]+h[(j+half)*n+i-half]+h[(j+half)*n+i+half]) + scale*u()
    for j in range(0, n, half):
        for i in range((half if (j // half) % 2 == 0 else 0), n, step):
            s = c = 0
            if i >= half: s += h[j*n+i-half]; c += 1
            if i + half < n: s += h[j*n+i+half]; c += 1
            if j >= half: s += h[(j-half)*n+i]; c += 1
            if j + half < n: s += h[(j+half)*n+i]; c += 1
            h[j*n+i] = s / c + scale * u()
    step //= 2; scale *= 0.5
lo = min(h)
with open(sys.argv[3], 'wb') as f:
    f.write(b'P5\n%d %d\n65535\n' % (n, n))
    f.write(b''.join(struct.pack('>H', min(65535, int(round(v - lo)))) for v in h))
