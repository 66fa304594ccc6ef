// ebcode against Draco 1.5.5 (docs/ebcode.md §6) on its real meshes and the
// 1.2 M-triangle subdivided bunny, in the same process: one JSON line per mesh and
// quantisation, with bytes, bits per vertex (connectivity and total), encode and decode
// throughput (median of 5 runs, one thread; wall clock and this thread's CPU time) for ebcode --conn auto (and the size with
// --predict multi against Draco cl10) and Draco cl7/cl10
// through libdraco, and draco_encoder's file size at cl7 when Debian's `draco` is installed.
//
//   build/bin/bench_ebm_vs_draco [TESTDATA_DIR] [--quick] [--runs N] [--only MESH]   (default: $FEST_TESTDATA)
//   build/bin/bench_ebm_vs_draco [TESTDATA_DIR] --profile MESH QP
//
// --profile codes one mesh (a name of the list below, or bunny_sub2) once with each coder
// and prints nothing else: for valgrind --tool=callgrind, whose inclusive instruction
// counts of encode_ebm, draco::Encoder::EncodeMeshToBuffer and
// draco::Decoder::DecodeMeshFromBuffer are then exactly one call each (deterministic,
// unlike wall-clock time on a shared machine); decode_ebm is called twice, without and
// with the re-encoding check, inside profile_decode and profile_verified_decode.
//
// Draco's connectivity is measured by encoding the same mesh with every position equal:
// its geometry then costs a few bytes, so the rest is connectivity and header (the
// harness subclasses MeshEdgebreakerEncoder instead; its figures are printed alongside as
// draco_conn_bpv_spec).

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include "core/file_io.hpp"
#include "edgebreaker/ebm.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace {

using namespace fest;
using namespace fest::edgebreaker;
using Clock = std::chrono::steady_clock;

// This thread's CPU time in ms: on a shared machine the time slices other processes take
// are not counted (cache refills after a switch still are).
double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

// Median wall-clock and median thread-CPU milliseconds of `runs` calls.
struct Timing {
  double wall_ms = 0, cpu_ms = 0;
};
Timing median_ms(int runs, const std::function<void()>& f) {
  std::vector<double> t, c;
  for (int i = 0; i < runs; ++i) {
    const auto start = Clock::now();
    const double cpu0 = thread_cpu_ms();
    f();
    c.push_back(thread_cpu_ms() - cpu0);
    t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  std::sort(c.begin(), c.end());
  return {t[t.size() / 2], c[c.size() / 2]};
}

long peak_rss_kb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

MeshSoup load(const std::string& path) {
  const formats::Input in = formats::load_input(path);
  const Mesh mesh = formats::parse(in, formats::read_mesh);
  MeshSoup soup;
  for (auto v : mesh.vertices()) soup.positions.push_back({mesh.point(v)[0], mesh.point(v)[1], mesh.point(v)[2]});
  for (auto f : mesh.faces()) {
    std::vector<int> p;
    for (auto v : mesh.fv_range(f)) p.push_back(v.idx());
    for (std::size_t k = 1; k + 1 < p.size(); ++k) soup.triangles.push_back({p[0], p[k], p[k + 1]});
  }
  return soup;
}

// 1 -> 4 midpoint subdivision.
MeshSoup subdivide(const MeshSoup& in) {
  MeshSoup out;
  out.positions = in.positions;
  std::map<std::pair<int, int>, int> mid;
  const auto midpoint = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto it = mid.find(key);
    if (it != mid.end()) return it->second;
    const auto& p = out.positions[static_cast<std::size_t>(a)];
    const auto& q = out.positions[static_cast<std::size_t>(b)];
    out.positions.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
    const int id = static_cast<int>(out.positions.size() - 1);
    mid.emplace(key, id);
    return id;
  };
  for (const Triangle& t : in.triangles) {
    const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    out.triangles.push_back({t[0], ab, ca});
    out.triangles.push_back({ab, t[1], bc});
    out.triangles.push_back({ca, bc, t[2]});
    out.triangles.push_back({ab, bc, ca});
  }
  return out;
}

std::unique_ptr<draco::Mesh> to_draco(const MeshSoup& soup, bool zero_positions) {
  auto mesh = std::make_unique<draco::Mesh>();
  mesh->set_num_points(static_cast<uint32_t>(soup.positions.size()));
  draco::GeometryAttribute a;
  a.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false, sizeof(float) * 3, 0);
  const int id = mesh->AddAttribute(a, true, static_cast<uint32_t>(soup.positions.size()));
  for (std::size_t v = 0; v < soup.positions.size(); ++v) {
    float p[3] = {0, 0, 0};
    if (!zero_positions)
      for (int k = 0; k < 3; ++k) p[k] = static_cast<float>(soup.positions[v][static_cast<std::size_t>(k)]);
    mesh->attribute(id)->SetAttributeValue(draco::AttributeValueIndex(static_cast<uint32_t>(v)), p);
  }
  for (const Triangle& t : soup.triangles)
    mesh->AddFace({draco::PointIndex(static_cast<uint32_t>(t[0])), draco::PointIndex(static_cast<uint32_t>(t[1])),
                   draco::PointIndex(static_cast<uint32_t>(t[2]))});
  return mesh;
}

std::string draco_encode(const draco::Mesh& mesh, int cl, int qp) {
  draco::Encoder encoder;
  encoder.SetSpeedOptions(10 - cl, 10 - cl);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, qp);
  encoder.SetEncodingMethod(draco::MESH_EDGEBREAKER_ENCODING);
  draco::EncoderBuffer buffer;
  if (!encoder.EncodeMeshToBuffer(mesh, &buffer).ok()) return {};
  return std::string(buffer.data(), buffer.size());
}

void draco_decode(const std::string& bytes) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  draco::Decoder decoder;
  auto mesh = decoder.DecodeMeshFromBuffer(&buffer);
  if (!mesh.ok()) std::abort();
}

// draco_encoder (Debian package draco) on an OBJ of the same mesh; -1 when not installed.
long draco_cli_bytes(const MeshSoup& soup, int cl, int qp) {
  if (std::system("command -v draco_encoder >/dev/null 2>&1") != 0) return -1;
  const std::string obj = "/tmp/bench_ebm_vs_draco.obj", drc = "/tmp/bench_ebm_vs_draco.drc";
  std::string text;
  for (const auto& p : soup.positions) text += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  for (const auto& t : soup.triangles)
    text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
  write_output(obj, text);
  const std::string cmd = "draco_encoder -i " + obj + " -o " + drc + " -cl " + std::to_string(cl) + " -qp " +
                          std::to_string(qp) + " >/dev/null 2>&1";
  if (std::system(cmd.c_str()) != 0) return -1;
  const long n = static_cast<long>(read_input(drc).size());
  std::remove(obj.c_str());
  std::remove(drc.c_str());
  return n;
}

// Draco cl7 connectivity (bpv), measured exactly by the harness of docs/ebcode.md §6.
double spec_draco_conn(const std::string& name) {
  static const std::map<std::string, double> table{{"bunny00", 1.974},   {"armadillo", 2.180}, {"ChineseDragon-10kv", 2.558},
                                                   {"camel", 0.988},     {"fandisk", 1.254}};
  const auto it = table.find(name);
  return it == table.end() ? -1 : it->second;
}

void bench(const std::string& name, const MeshSoup& soup, int qp, int runs) {
  const double v = static_cast<double>(soup.positions.size());
  const double t = static_cast<double>(soup.triangles.size());
  EncodeOptions o;
  o.qp = qp;
  o.verify = false;  // the decoder's re-encoding check is a test, not part of coding
  EncodeStats stats;
  std::string ebm;
  const Timing enc = median_ms(runs, [&] { ebm = encode_ebm(soup, o, &stats); });
  const Timing dec = median_ms(runs, [&] { decode_ebm(ebm, true, false); });
  const Timing dec_verified = median_ms(runs, [&] { decode_ebm(ebm, true, true); });
  const std::size_t conn = stats.section_bytes.count("CONN") ? stats.section_bytes.at("CONN") : 0;
  EncodeOptions om = o;
  om.predictor = Predictor::multi;
  const std::size_t multi_bytes = encode_ebm(soup, om).size();

  const auto draco_mesh = to_draco(soup, false);
  const auto draco_flat = to_draco(soup, true);
  std::string d7, d10;
  const Timing d7_enc = median_ms(runs, [&] { d7 = draco_encode(*draco_mesh, 7, qp); });
  const Timing d7_dec = median_ms(runs, [&] { draco_decode(d7); });
  const Timing d10_enc = median_ms(runs, [&] { d10 = draco_encode(*draco_mesh, 10, qp); });
  const Timing d10_dec = median_ms(runs, [&] { draco_decode(d10); });
  const std::size_t d7_conn = draco_encode(*draco_flat, 7, qp).size();
  const long cli = draco_cli_bytes(soup, 7, qp);

  // *_ms: median wall clock; *_cpu_ms: median CPU time of this thread (what to compare on
  // a loaded machine); M tri/s from the CPU time.
  std::printf(
      "{\"bench\":\"ebm_vs_draco\",\"mesh\":\"%s\",\"vertices\":%.0f,\"triangles\":%.0f,\"qp\":%d,\"runs\":%d,"
      "\"ebm\":{\"bytes\":%zu,\"geom_version\":%d,\"conn_mode\":\"%s\",\"conn_bpv\":%.4f,\"total_bpv\":%.3f,\"encode_ms\":%.2f,"
      "\"decode_ms\":%.2f,\"decode_verified_ms\":%.2f,\"encode_cpu_ms\":%.2f,\"decode_cpu_ms\":%.2f,"
      "\"decode_verified_cpu_ms\":%.2f,\"encode_mtri_s\":%.3f,\"decode_mtri_s\":%.3f,\"decode_verified_mtri_s\":%.3f},"
      "\"draco_cl7\":{\"bytes\":%zu,\"conn_bpv_flat\":%.4f,\"total_bpv\":%.3f,\"encode_ms\":%.2f,\"decode_ms\":%.2f,"
      "\"encode_cpu_ms\":%.2f,\"decode_cpu_ms\":%.2f,\"encode_mtri_s\":%.3f,\"decode_mtri_s\":%.3f},"
      "\"draco_cl10\":{\"bytes\":%zu,\"total_bpv\":%.3f,\"encode_ms\":%.2f,\"decode_ms\":%.2f,\"encode_cpu_ms\":%.2f,"
      "\"decode_cpu_ms\":%.2f},"
      "\"ebm_multi_bytes\":%zu,\"ebm_multi_over_draco_cl10\":%.4f,\"draco_encoder_cl7_bytes\":%ld,\"draco_conn_bpv_spec\":%.3f,"
      "\"ebm_over_draco_cl7_bytes\":%.4f,\"conn_vs_draco_cl7\":%.4f,\"encode_cpu_draco_cl7_over_ebm\":%.3f,"
      "\"decode_cpu_draco_cl7_over_ebm\":%.3f,\"decode_verified_cpu_draco_cl7_over_ebm\":%.3f,\"peak_rss_kb\":%ld%s}\n",
      name.c_str(), v, t, qp, runs, ebm.size(), ebm[9] == 1 ? 3 : 2, stats.conn_mode.c_str(), 8.0 * static_cast<double>(conn) / v,
      8.0 * static_cast<double>(ebm.size()) / v, enc.wall_ms, dec.wall_ms, dec_verified.wall_ms, enc.cpu_ms, dec.cpu_ms,
      dec_verified.cpu_ms, t / enc.cpu_ms / 1000.0, t / dec.cpu_ms / 1000.0, t / dec_verified.cpu_ms / 1000.0, d7.size(),
      8.0 * static_cast<double>(d7_conn) / v, 8.0 * static_cast<double>(d7.size()) / v, d7_enc.wall_ms, d7_dec.wall_ms,
      d7_enc.cpu_ms, d7_dec.cpu_ms, t / d7_enc.cpu_ms / 1000.0, t / d7_dec.cpu_ms / 1000.0, d10.size(),
      8.0 * static_cast<double>(d10.size()) / v, d10_enc.wall_ms, d10_dec.wall_ms, d10_enc.cpu_ms, d10_dec.cpu_ms,
      multi_bytes, static_cast<double>(multi_bytes) / static_cast<double>(d10.size()), cli, spec_draco_conn(name),
      static_cast<double>(ebm.size()) / static_cast<double>(d7.size()), static_cast<double>(conn) / static_cast<double>(d7_conn),
      d7_enc.cpu_ms / enc.cpu_ms, d7_dec.cpu_ms / dec.cpu_ms, d7_dec.cpu_ms / dec_verified.cpu_ms, peak_rss_kb(),
      cli < 0 ? ",\"note\":\"draco_encoder not installed (Debian package draco)\"" : "");
  std::fflush(stdout);
}

// Each decode in a function of its own, so that callgrind counts them apart (and
// --toggle-collect can pick one).
[[gnu::noinline]] MeshSoup profile_decode(const std::string& ebm) { return decode_ebm(ebm, true, false); }
[[gnu::noinline]] MeshSoup profile_verified_decode(const std::string& ebm) { return decode_ebm(ebm, true, true); }

// One call of each coder (see --profile above).
void profile(const MeshSoup& soup, int qp) {
  EncodeOptions o;
  o.qp = qp;
  o.verify = false;
  const std::string ebm = encode_ebm(soup, o);
  const MeshSoup back = profile_decode(ebm);
  const MeshSoup checked = profile_verified_decode(ebm);
  const auto draco_mesh = to_draco(soup, false);
  const std::string d7 = draco_encode(*draco_mesh, 7, qp);
  draco_decode(d7);
  std::printf("{\"bench\":\"ebm_vs_draco_profile\",\"triangles\":%zu,\"qp\":%d,\"ebm_bytes\":%zu,\"draco_cl7_bytes\":%zu}\n",
              soup.triangles.size(), qp, ebm.size(), d7.size());
}

}  // namespace

int main(int argc, char** argv) {
  std::string dir;
  bool quick = false;
  int runs = 5;
  std::string only;  // one mesh of the list (or bunny_sub2), for a quicker run
  std::string profile_mesh;
  int profile_qp = 14;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") quick = true;
    else if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--only" && i + 1 < argc) only = argv[++i];
    else if (a == "--profile" && i + 2 < argc) {
      profile_mesh = argv[++i];
      profile_qp = std::atoi(argv[++i]);
    } else dir = a;
  }
  if (dir.empty()) {
    const char* env = std::getenv("FEST_TESTDATA");
    const char* home = std::getenv("HOME");
    dir = env ? env : std::string(home ? home : ".") + "/.cache/fest/testdata";
  }
  try {
    if (!profile_mesh.empty()) {
      const bool sub = profile_mesh == "bunny_sub2";
      const MeshSoup soup = load(dir + "/meshes/" + (sub ? std::string("bunny00") : profile_mesh) + ".off");
      profile(sub ? subdivide(subdivide(soup)) : soup, profile_qp);
      return 0;
    }
    MeshSoup bunny;
    if (quick) runs = 1;
    for (const char* name : {"bunny00", "armadillo", "ChineseDragon-10kv", "camel", "fandisk"}) {
      if (!only.empty() && only != name && !(only == "bunny_sub2" && std::string(name) == "bunny00")) continue;
      const std::string path = dir + "/meshes/" + name + ".off";
      MeshSoup soup;
      try {
        soup = load(path);
      } catch (const Error& e) {
        std::printf("{\"bench\":\"ebm_vs_draco\",\"mesh\":\"%s\",\"skipped\":\"%s\"}\n", name, e.what());
        continue;
      }
      if (only != "bunny_sub2")
        for (int qp : {11, 14}) bench(name, soup, qp, runs);
      if (std::string(name) == "bunny00") bunny = soup;
    }
    if (!bunny.triangles.empty() && (only.empty() || only == "bunny_sub2")) bench("bunny_sub2", subdivide(subdivide(bunny)), 14, runs);
  } catch (const Error& e) {
    std::fprintf(stderr, "bench_ebm_vs_draco: error: %s\n", e.what());
    return e.exit_code();
  }
  return 0;
}
