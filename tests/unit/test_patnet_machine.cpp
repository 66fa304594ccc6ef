// PaT-Net semantics (docs/patnet.md "Scheduler"): the seed's worked example, waits,
// monitors, inheritance, exits, probabilistic arcs.

#include <gtest/gtest.h>

#include <pthread.h>

#include <cmath>
#include <map>

#include "core/error.hpp"
#include "patnet/machine.hpp"
#include "patnet/markov.hpp"

using namespace fest::patnet;

namespace {

struct Recorder : TraceSink {
  std::vector<Event> events;
  std::vector<std::string> labels;
  void event(const Event& e) override {
    events.push_back(e);
    // string_views point into the machine; copy what the tests read
    Event& c = events.back();
    store.push_back(std::string(e.node));
    c.node = store.back();
    store.push_back(std::string(e.to));
    c.to = store.back();
    labels.push_back(e.inst != nullptr ? e.inst->label : "");
  }
  std::deque<std::string> store;
  std::vector<std::int64_t> cycles(Event::Kind k, const std::string& label, const std::string& node = "") const {
    std::vector<std::int64_t> r;
    for (std::size_t i = 0; i < events.size(); ++i)
      if (events[i].kind == k && labels[i] == label && (node.empty() || events[i].node == node)) r.push_back(events[i].cycle);
    return r;
  }
  std::string status_of(const std::string& label) const {
    for (std::size_t i = 0; i < events.size(); ++i)
      if ((events[i].kind == Event::Kind::exit || events[i].kind == Event::Kind::kill) && labels[i] == label) return events[i].text;
    return "";
  }
};

const char* samp = R"(
(defnet samp-fsm :locals '(a b)
  (definit (a b) (val a a) (val b b))
  (defaction :inca (val a (1+ (val a))))
  (defaction :incb (val b (1+ (val b))))
  (defcond :c1 (< (val a) 6))
  (defcond :c2 (< (val b) 5))
  (defnode state1 :inca (:default state2))
  (defnode state2 :no-op (:c1 state1) (:default state3))
  (defnode state3 :incb (:default state4))
  (defnode state4 :no-op (:c2 state3) (:default exit)))
(setf fred (send samp-fsm :new 1 2))
(setf sam  (send samp-fsm :new 3 3))
)";

Value local(const Machine& m, const Instance& i, const std::string& name) {
  for (std::size_t k = 0; k < i.locals.size(); ++k)
    if (m.symbol_name(i.cls->local_names[k]) == name) return i.locals[k];
  return Value::nil();
}

}  // namespace

// Seed App. A §1 with the cycle rules: the cycle lists are derived by hand (docs/patnet.md).
TEST(PatnetMachine, WorkedExampleCycles) {
  Recorder rec;
  Machine m({}, &rec);
  m.load(samp, "samp.pat", true);
  const RunSummary s = m.run();
  EXPECT_EQ(s.cycles, 16);
  using V = std::vector<std::int64_t>;
  EXPECT_EQ(rec.cycles(Event::Kind::enter, "samp-fsm#1", "STATE1"), (V{1, 3, 5, 7, 9}));
  EXPECT_EQ(rec.cycles(Event::Kind::enter, "samp-fsm#1", "STATE2"), (V{2, 4, 6, 8, 10}));
  EXPECT_EQ(rec.cycles(Event::Kind::enter, "samp-fsm#1", "STATE3"), (V{11, 13, 15}));
  EXPECT_EQ(rec.cycles(Event::Kind::enter, "samp-fsm#1", "STATE4"), (V{12, 14, 16}));
  EXPECT_EQ(rec.cycles(Event::Kind::exit, "samp-fsm#1"), (V{16}));
  EXPECT_EQ(rec.cycles(Event::Kind::enter, "samp-fsm#2", "STATE3"), (V{7, 9}));
  EXPECT_EQ(rec.cycles(Event::Kind::exit, "samp-fsm#2"), (V{10}));
  for (const auto& i : m.instances()) {
    EXPECT_EQ(local(m, *i, "A").u.i, 6);
    EXPECT_EQ(local(m, *i, "B").u.i, 5);
  }
}

TEST(PatnetMachine, SpawnAndWaitFsm) {
  // App. A §3B: the child starts the next cycle; the parent (lower id) sees the child's
  // exit one cycle late.
  Recorder rec;
  Machine m({}, &rec);
  m.load(R"(
(defnet child (defnode c1 :no-op (:default c2)) (defnode c2 :no-op (:default exit)))
(defnet parent :locals '(waiting-for)
  (defaction :spawn (val waiting-for (send child :new)) (send self :wait-fsm (val waiting-for)))
  (defnode p1 :spawn (:default p2))
  (defnode p2 :no-op (:default exit)))
(send parent :new))", "t.pat", true);
  m.run();
  using V = std::vector<std::int64_t>;
  EXPECT_EQ(rec.cycles(Event::Kind::enter, "child#2", "C1"), (V{2}));   // created at 1, runs at 2
  EXPECT_EQ(rec.cycles(Event::Kind::exit, "child#2"), (V{3}));
  EXPECT_EQ(rec.cycles(Event::Kind::resume, "parent#1"), (V{4}));      // e + 1
  EXPECT_EQ(rec.cycles(Event::Kind::enter, "parent#1", "P2"), (V{5}));
}

TEST(PatnetMachine, WaitForStateAndKillWhenItExits) {
  Recorder rec;
  Machine m({}, &rec);
  m.load(R"(
(defnet target (defnode s1 :no-op (:default s2)) (defnode s2 :no-op (:default s3)) (defnode s3 :no-op (:default exit)))
(defnet skipper (defnode s1 :no-op (:default exit)) (defnode s2 :no-op (:default exit)))
(defnet watcher :locals '(x)
  (definit (x) (val x x))
  (defaction :w (send self :wait-fsm (val x) :state 's2))
  (defnode w1 :w (:default exit)))
(defnet late-watcher (defaction :w (send self :wait-fsm hi :state 's2)) (defnode w1 :w (:default exit)))
(setf lo (send target :new))
(setf w1 (send watcher :new lo))
(setf w2 (send late-watcher :new))
(setf hi (send target :new))
(setf sk (send skipper :new))
(setf w3 (send watcher :new sk)))", "t.pat", true);
  m.run();
  using V = std::vector<std::int64_t>;
  // target#1 (lower id than watcher#2) enters S2 at 2: the watcher resumes at 2.
  EXPECT_EQ(rec.cycles(Event::Kind::resume, "watcher#2"), (V{2}));
  // target#4 (higher id than late-watcher#3) enters S2 at 2: resume at 3.
  EXPECT_EQ(rec.cycles(Event::Kind::resume, "late-watcher#3"), (V{3}));
  // skipper#5 exits at 1 without passing S2: watcher#6 is killed then.
  EXPECT_EQ(rec.status_of("watcher#6"), "failed");
  EXPECT_EQ(rec.cycles(Event::Kind::kill, "watcher#6"), (V{1}));
}

TEST(PatnetMachine, WaitTimeIsExactlyNinetyCycles) {
  Recorder rec;
  Machine m({}, &rec);
  m.load(R"(
(defnet sleeper
  (defaction :sleep (send self :wait-time (+ (motion-time) 3.0)))
  (defnode a :no-op (:default b))
  (defnode b :sleep (:default exit)))
(send sleeper :new))", "t.pat", true);
  m.run();
  EXPECT_EQ(rec.cycles(Event::Kind::enter, "sleeper#1", "B"), (std::vector<std::int64_t>{2}));
  EXPECT_EQ(rec.cycles(Event::Kind::resume, "sleeper#1"), (std::vector<std::int64_t>{92}));
}

TEST(PatnetMachine, MonitorsRunWhileWaitingAndDefaultShadows) {
  Recorder rec;
  Machine m({}, &rec);
  m.load(R"(
(setf flag nil)
(defnet mon :locals '(n hits)
  (definit () (val n 0) (val hits 0))
  (defaction :count (val hits (+ (val hits) 1)))
  (defcond :tick (progn (val n (+ (val n) 1)) t))
  (defcond :never nil)
  (defaction :block (send self :wait-condition #'(lambda () flag)))
  (defmonitor m1 :tick :count)
  (defnode a :block (:default b) (:never a))
  (defnode b :no-op (:default exit)))
(setf it (send mon :new)))", "t.pat", true);
  // Run five cycles waiting, then release the condition.
  std::vector<InputEvent> in(1);
  in[0].kind = InputEvent::Kind::eval;
  in[0].t = 5.0 / 30.0;
  in[0].name = "(setf flag t)";
  m.set_inputs(in);
  m.run();
  const Instance& i = *m.instances()[0];
  EXPECT_EQ(local(m, i, "HITS").u.i, 6);  // the monitor ran on cycles 1..6, also while waiting
  EXPECT_EQ(rec.cycles(Event::Kind::resume, "mon#1"), (std::vector<std::int64_t>{5}));
  EXPECT_EQ(rec.cycles(Event::Kind::enter, "mon#1", "A").size(), 1u);  // action runs once per entry
}

TEST(PatnetMachine, InheritanceOverrideC3AndClassVariables) {
  Recorder rec;
  Machine m({}, &rec);
  m.load(R"(
(defnet base :locals '(x) :class-vars '(shared)
  (defaction :set (val x 'base) (val shared (+ 1 (if (val shared) (val shared) 0))))
  (defnode s1 :set (:default exit)))
(defnet left :parents (list base) (defaction :set (val x 'left) (val shared (+ 10 (if (val shared) (val shared) 0)))))
(defnet right :parents (list base))
(defnet both :parents (list left right))
(setf i1 (send both :new))
(setf i2 (send right :new)))", "t.pat", true);
  m.run();
  const NetClass* both = m.instances()[0]->cls;
  std::vector<std::string> cpl;
  for (const NetClass* c : both->cpl) cpl.push_back(c->print_name);
  EXPECT_EQ(cpl, (std::vector<std::string>{"both", "left", "right", "base"}));
  EXPECT_EQ(m.print(local(m, *m.instances()[0], "X"), false), "LEFT");
  EXPECT_EQ(m.print(local(m, *m.instances()[1], "X"), false), "BASE");
  // SHARED is base's class variable, shared by every subclass instance: 10 + 1.
  const Value* shared = m.instances()[0]->cls->find_classvar(m.instances()[0]->cls->cpl.back()->own_classvars[0]);
  ASSERT_NE(shared, nullptr);
  EXPECT_EQ(shared->u.i, 11);
}

TEST(PatnetMachine, ExitKillsDependentsRecursively) {
  Recorder rec;
  Machine m({}, &rec);
  m.load(R"(
(defnet idle (defnode s :no-op (:never s)) (defcond :never nil))
(defnet boss (defaction :quit (send self :exit 'failed) (send self :wait-time 100)) (defnode s :quit (:default exit)))
(setf a (send boss :new))
(setf b (send idle :new))
(setf c (send idle :new))
(send a :add-dependent b)
(send b :add-dependent c))", "t.pat", true);
  m.run();
  EXPECT_EQ(rec.status_of("boss#1"), "failed");
  EXPECT_EQ(rec.status_of("idle#2"), "failed");
  EXPECT_EQ(rec.status_of("idle#3"), "failed");
  EXPECT_EQ(rec.cycles(Event::Kind::kill, "idle#3"), (std::vector<std::int64_t>{1}));
}

TEST(PatnetMachine, LanguageBasics) {
  Machine m;
  m.load("(defun sq (x &optional (y 2)) (expt x y)) (defun kw (&key (priority 1.0) state) (list priority state))", "t.pat", true);
  EXPECT_EQ(m.print(m.eval_text("(+ 1 2.5)", "e"), false), "3.5");
  EXPECT_EQ(m.print(m.eval_text("(/ 6 3)", "e"), false), "2");
  EXPECT_EQ(m.print(m.eval_text("(/ 7 2)", "e"), false), "3.5");
  EXPECT_EQ(m.print(m.eval_text("(sq 3)", "e"), false), "9");
  EXPECT_EQ(m.print(m.eval_text("(kw :state 's2)", "e"), false), "(1.0 S2)");
  EXPECT_EQ(m.print(m.eval_text("(let ((x 1)) (let* ((x 2) (y x)) y))", "e"), false), "2");
  EXPECT_EQ(m.print(m.eval_text("(format nil \"a~a ~s ~d~~~%\" 'x \"q\" 4)", "e"), true), "\"aX \\\"q\\\" 4~\n\"");
  EXPECT_EQ(m.print(m.eval_text("(let ((n 0)) (dolist (i '(1 2 3) n) (setq n (+ n i))))", "e"), false), "6");
  EXPECT_EQ(m.print(m.eval_text("(funcall (let ((k 5)) #'(lambda (z) (+ k z))) 1)", "e"), false), "6");
  EXPECT_EQ(m.print(m.eval_text("(cadr (assoc 'b '((a 1) (b 2))))", "e"), false), "2");
  EXPECT_EQ(m.print(m.eval_text("(mod -7 3)", "e"), false), "2");
  EXPECT_EQ(m.print(m.eval_text("(expt 3 13)", "e"), false), "1594323");
  EXPECT_EQ(m.print(m.eval_text("(expt 1 4000000000000)", "e"), false), "1");  // no loop over the exponent
  EXPECT_EQ(m.print(m.eval_text("(expt 2 64)", "e"), false), "1.8446744073709552e+19");
  EXPECT_EQ(m.print(m.eval_text("(dotimes (i 10) (when (= i 4) (return (* i i))))", "e"), false), "16");
  EXPECT_THROW(m.eval_text("(return 1)", "e"), LispError);  // outside a loop: refused when compiled
  EXPECT_THROW(m.eval_text("(dolist (x '(1)) (funcall #'(lambda () (return x))))", "e"), LispError);
  EXPECT_THROW(m.eval_text("(car 5)", "e"), LispError);
  EXPECT_THROW(m.eval_text("undefined-var", "e"), LispError);
}

// Seed App. A 1E: (0.1 state1) (0.7 state2) (0.2 state3). 10,000 draws; each frequency
// within its 99.9 % binomial interval (+-3.29 sigma).
TEST(PatnetMachine, ProbabilisticArcsMatchTheirProbabilities) {
  Recorder rec;
  RunOptions o;
  o.seed = 12345;
  o.cycles = 10000;
  Machine m(o, &rec);
  m.load(R"(
(defnet pn
  (def-probnode state1 :no-op (0.1 state1) (0.7 state2) (0.2 state3))
  (defnode state2 :no-op (:default state1))
  (defnode state3 :no-op (:default state1)))
(send pn :new))", "t.pat", true);
  m.run();
  std::map<std::string, int> n;
  int draws = 0;
  for (const Event& e : rec.events)
    if (e.kind == Event::Kind::arc && e.prob >= 0) {
      ++n[std::string(e.to)];
      ++draws;
    }
  ASSERT_GT(draws, 5000);
  const std::map<std::string, double> p{{"STATE1", 0.1}, {"STATE2", 0.7}, {"STATE3", 0.2}};
  for (auto& [k, pk] : p) {
    const double sigma = std::sqrt(pk * (1 - pk) / draws);
    EXPECT_NEAR(static_cast<double>(n[k]) / draws, pk, 3.29 * sigma) << k;
  }
}

TEST(PatnetMachine, HalfProbabilityStaysHalfTheTime) {
  Recorder rec;
  RunOptions o;
  o.seed = 7;
  o.cycles = 10000;
  Machine m(o, &rec);
  m.load("(defnet h (def-probnode s :no-op (0.5 s)) ) (send h :new)", "t.pat", true);
  m.run();
  int arcs = 0;
  for (const Event& e : rec.events) arcs += e.kind == Event::Kind::arc;
  // Each cycle either takes the arc (re-entering next cycle) or stays; entries ~ cycles/2 ... 
  // P(arc per cycle) = 0.5 exactly, sigma = sqrt(0.25/10000) = 0.005.
  EXPECT_NEAR(arcs / 10000.0, 0.5, 3.29 * 0.005);
}

TEST(PatnetMachine, SameSeedSameTraceOtherSeedOther) {
  auto trace = [](std::uint64_t seed) {
    Recorder rec;
    RunOptions o;
    o.seed = seed;
    o.cycles = 200;
    Machine m(o, &rec);
    m.load("(defnet r (def-randnode a :no-op a b c) (defnode b :no-op (:default a)) (defnode c :no-op (:default a))) (send r :new)",
           "t.pat", true);
    m.run();
    std::string s;
    for (const Event& e : rec.events) s += std::string(e.to) + ",";
    return s;
  };
  EXPECT_EQ(trace(3), trace(3));
  EXPECT_NE(trace(3), trace(4));
}

TEST(PatnetMachine, StaticErrors) {
  Machine m;
  m.load("(defnet bad (defcond c1 t) (defnode s1 :nope (:c2 s9)) (def-probnode s2 :no-op (0.6 s1) (0.6 s1)))", "bad.pat", false);
  m.finish_checks();
  std::string all;
  for (const auto& d : m.diagnostics()) all += d.text() + "\n";
  EXPECT_NE(all.find("condition name C1 must start with ':' (bad.pat:1:22)"), std::string::npos) << all;
  EXPECT_NE(all.find("undefined action :NOPE"), std::string::npos) << all;
  EXPECT_NE(all.find("undefined condition :C2"), std::string::npos) << all;
  EXPECT_NE(all.find("undefined node S9"), std::string::npos) << all;
  EXPECT_NE(all.find("sum to 1.2"), std::string::npos) << all;
  Machine e;
  EXPECT_THROW(e.load("(defnet x (defnode a :no-op (:default zz)))", "x.pat", true), fest::Error);
}

TEST(PatnetMachine, RunawayCodeHitsTheStepLimit) {
  RunOptions o;
  o.max_steps = 10000;
  Machine m(o, nullptr);
  m.load("(defnet x (defaction :spin (dotimes (i 1000000) i)) (defnode a :spin (:default exit))) (send x :new)", "x.pat", true);
  EXPECT_THROW(m.run(), fest::Error);
}

// Unbounded recursion stops with a message whatever the stack: the depth limit (2000
// calls) on the main thread, the stack budget on a 256 KiB thread, where 2000 calls do
// not fit (a sanitizer build overflowed 8 MiB the same way).
TEST(PatnetMachine, RecursionStopsBeforeTheStackEnds) {
  const char* rec = "(defun f (n) (f n)) (defnet x (defaction :go (f 1)) (defnode a :go (:default exit))) (send x :new)";
  auto run_once = [rec] {
    Machine m({}, nullptr);
    m.load(rec, "rec.pat", true);
    try {
      m.run();
    } catch (const fest::Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(run_once().find("nested deeper"), std::string::npos);

  struct Job {
    decltype(run_once)* fn;
    std::string message;
  } job{&run_once, {}};
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, 256 * 1024);
  pthread_t t;
  ASSERT_EQ(pthread_create(&t, &attr, [](void* p) -> void* {
    auto* j = static_cast<Job*>(p);
    j->message = (*j->fn)();
    return nullptr;
  }, &job), 0);
  pthread_join(t, nullptr);
  pthread_attr_destroy(&attr);
  EXPECT_NE(job.message.find("than the stack allows"), std::string::npos) << job.message;
}

TEST(PatnetMachine, DeadlockIsReported) {
  Recorder rec;
  Machine m({}, &rec);
  m.load(R"(
(setf s (send semaphore :new 0))
(defnet w (defaction :take (send self :wait-semaphore s)) (defnode a :take (:default exit)))
(send w :new))", "d.pat", true);
  const RunSummary r = m.run();
  EXPECT_TRUE(r.deadlock);
  EXPECT_EQ(rec.events.back().kind, Event::Kind::deadlock);
}

// markov round trip (docs/patnet.md "markov"): a known 3-state chain sampled 10^5 steps
// and re-estimated: every entry within 0.01.
TEST(PatnetMarkov, EstimateRecoversAKnownChain) {
  const double P[3][3] = {{0.5, 0.3, 0.2}, {0.1, 0.8, 0.1}, {0.3, 0.3, 0.4}};
  fest::Rng rng(99);
  std::vector<int> seq{0};
  for (int k = 0; k < 100000; ++k) {
    const double u = rng.uniform();
    const int i = seq.back();
    int j = 0;
    double c = P[i][0];
    while (u >= c && j < 2) c += P[i][++j];
    seq.push_back(j);
  }
  const MarkovEstimate e = estimate_markov(seq, 3, false);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(e.p[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], P[i][j], 0.01);
  EXPECT_EQ(gaze_state(5, 1, 1), 23);
  EXPECT_EQ(gaze_state(6, 0, 0), -1);
  EXPECT_TRUE(estimate_markov({0, 0, 1}, 4, false).unvisited == (std::vector<int>{1, 2, 3}));
}

TEST(PatnetMachine, LongListsDoNotOverflowTheStack) {
  RunOptions o;
  o.max_steps = 100000000;
  Machine m(o, nullptr);
  m.load("(setq l nil) (dotimes (i 1000000) (setq l (cons i l)))", "t.pat", true);
  EXPECT_EQ(m.print(m.eval_text("(length l)", "e"), false), "1000000");
  EXPECT_EQ(m.print(m.eval_text("(equal l (reverse (reverse l)))", "e"), false), "T");
  m.eval_text("(setq l nil)", "e");  // frees a million cells in a loop
  m.load("(setq d nil) (dotimes (i 5000) (setq d (list d)))", "t2.pat", true);
  EXPECT_NE(m.print(m.eval_text("d", "e"), false).find("..."), std::string::npos);
}

// Ten seeds, 10,000 cycles each: Pearson's chi-square of the 10/70/20 % node against its
// probabilities, 2 degrees of freedom, below 13.82 (p > 0.001) for every seed.
TEST(PatnetMachine, ProbabilisticNodeChiSquareOverTenSeeds) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Recorder rec;
    RunOptions o;
    o.seed = seed;
    o.cycles = 10000;
    Machine m(o, &rec);
    m.load("(defnet pn (def-probnode s1 :no-op (0.1 s1) (0.7 s2) (0.2 s3)) (defnode s2 :no-op (:default s1))"
           " (defnode s3 :no-op (:default s1))) (send pn :new)", "t.pat", true);
    m.run();
    double n[3] = {0, 0, 0};
    for (const Event& e : rec.events)
      if (e.kind == Event::Kind::arc && e.prob >= 0) n[e.to == "S1" ? 0 : e.to == "S2" ? 1 : 2] += 1;
    const double total = n[0] + n[1] + n[2], p[3] = {0.1, 0.7, 0.2};
    double chi2 = 0;
    for (int k = 0; k < 3; ++k) chi2 += (n[k] - total * p[k]) * (n[k] - total * p[k]) / (total * p[k]);
    EXPECT_LT(chi2, 13.82) << "seed " << seed;
  }
}

TEST(PatnetMachine, ClosuresCaptureTheirInstance) {
  Machine m;
  m.load(R"(
(defnet holder :locals '(n)
  (definit (n) (val n n))
  (defaction :share (setf getter #'(lambda () (val n))))
  (defnode s :share (:default exit)))
(send holder :new 41))", "t.pat", true);
  m.run();
  EXPECT_EQ(m.print(m.eval_text("(+ 1 (funcall getter))", "e"), false), "42");
}
