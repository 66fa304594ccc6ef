// patnet's step rate against an SCXML interpreter measured in the same run (docs/patnet.md
// "Performance"): Qt SCXML (Debian libqt5scxml5-dev; 141/159 W3C tests per the
// scxml-tutorial table), N machines of a 16-state ring advanced by one "tick" event per
// cycle, against patnet with N instances of the same ring advanced by :default arcs (one
// node per cycle). Both single-threaded, no tracing. One JSON line per system.

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <QBuffer>
#include <QCoreApplication>
#include <QScxmlStateMachine>

#include "patnet/machine.hpp"

using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  const int n = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int cycles = argc > 2 ? std::atoi(argv[2]) : 1000;
  const int ring = 16;

  QByteArray doc = "<scxml xmlns='http://www.w3.org/2005/07/scxml' version='1.0' datamodel='null' initial='s0'>";
  for (int i = 0; i < ring; ++i)
    doc += QByteArray("<state id='s") + QByteArray::number(i) + "'><transition event='tick' target='s" +
           QByteArray::number((i + 1) % ring) + "'/></state>";
  doc += "</scxml>";
  std::vector<QScxmlStateMachine*> ms;
  for (int i = 0; i < n; ++i) {
    QBuffer buf(&doc);
    buf.open(QIODevice::ReadOnly);
    QScxmlStateMachine* m = QScxmlStateMachine::fromData(&buf);
    if (m == nullptr || !m->parseErrors().isEmpty()) {
      std::fprintf(stderr, "bench_patnet_scxml: the SCXML document does not load\n");
      return 1;
    }
    m->start();
    ms.push_back(m);
  }
  app.processEvents();
  auto t0 = Clock::now();
  std::clock_t c0 = std::clock();
  for (int c = 0; c < cycles; ++c) {
    for (QScxmlStateMachine* m : ms) m->submitEvent(QStringLiteral("tick"));
    app.processEvents();
  }
  const double qt_wall = std::chrono::duration<double>(Clock::now() - t0).count();
  const double qt_s = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;  // CPU: fair on a shared machine
  // Where did machine 0 end? cycles ticks from s0: s(cycles mod 16).
  const bool qt_ok = ms[0]->activeStateNames().contains(QStringLiteral("s") + QString::number(cycles % ring));
  std::printf("{\"case\":\"ring16_qt_scxml\",\"machines\":%d,\"cycles\":%d,\"wall_seconds\":%.3f,\"cpu_seconds\":%.3f,\"steps_per_cpu_s\":%.4g,\"final_state_ok\":%s}\n",
              n, cycles, qt_wall, qt_s, static_cast<double>(n) * cycles / qt_s, qt_ok ? "true" : "false");
  std::fflush(stdout);
  for (QScxmlStateMachine* m : ms) delete m;

  std::string net = "(defnet ring";
  for (int i = 0; i < ring; ++i) net += " (defnode s" + std::to_string(i) + " :no-op (:default s" + std::to_string((i + 1) % ring) + "))";
  net += ")\n(dotimes (i " + std::to_string(n) + ") (send ring :new))\n";
  fest::patnet::RunOptions opt;
  opt.cycles = cycles;
  struct Count : fest::patnet::TraceSink {
    long long enters = 0;
    void event(const fest::patnet::Event& e) override { enters += e.kind == fest::patnet::Event::Kind::enter; }
  } sink;
  fest::patnet::Machine m(opt, &sink);
  m.load(net, "ring.pat", true);
  t0 = Clock::now();
  c0 = std::clock();
  m.run();
  const double pn_wall = std::chrono::duration<double>(Clock::now() - t0).count();
  const double pn_s = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  std::printf("{\"case\":\"ring16_patnet\",\"instances\":%d,\"cycles\":%d,\"wall_seconds\":%.3f,\"cpu_seconds\":%.3f,\"steps_per_cpu_s\":%.4g,\"enters\":%lld,"
              "\"speedup_vs_qt_scxml\":%.3g}\n",
              n, cycles, pn_wall, pn_s, static_cast<double>(n) * cycles / pn_s, sink.enters, qt_s / pn_s);
  return 0;
}
