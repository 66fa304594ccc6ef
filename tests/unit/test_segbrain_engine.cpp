// Engine semantics (docs/segbrain.md §2): clause order, backtracking,
// cut scoping, if-then-else, negation, findall, arithmetic, errors, limits, and the
// release of workspace objects on backtracking.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "segbrain/engine.hpp"
#include "segbrain/kb_parser.hpp"
#include "segbrain/workspace.hpp"

using namespace fest::segbrain;

namespace {

Engine with(const std::string& kb) {
  Engine e;
  e.consult(parse_program(kb, "t.pl"));
  return e;
}

// Every value of X that proves the goal, as a printed list.
std::string solve1(Engine& e, const std::string& goal_text) {
  // findall with a goal that names X: parsed as one term so X is shared.
  Term both = parse_term("findall(X, (" + goal_text + "), L)", "goal");
  Term l = deref(both)->args[2];
  EXPECT_TRUE(e.prove(both));
  return to_string(l);
}

}  // namespace

TEST(SegbrainEngine, ClauseOrderAndBacktracking) {
  Engine e = with("p(1). p(2). p(3). q(X) :- p(X), X > 1.");
  EXPECT_EQ(solve1(e, "q(X)"), "[2, 3]");
  EXPECT_EQ(solve1(e, "member(X, [a, b, c])"), "[a, b, c]");
  EXPECT_EQ(solve1(e, "between(1, 4, X)"), "[1, 2, 3, 4]");
}

TEST(SegbrainEngine, CutIsLocalToItsClause) {
  Engine e = with(
      "a(1). a(2). a(3).\n"
      "first(X) :- a(X), !.\n"
      "inner(X) :- first(X).\n"
      "inner(9).\n"
      "outer(X) :- inner(X).\n");
  EXPECT_EQ(solve1(e, "first(X)"), "[1]");
  // The cut inside first/1 does not remove inner/1's second clause.
  EXPECT_EQ(solve1(e, "outer(X)"), "[1, 9]");
  // call/1 is opaque to cut.
  EXPECT_EQ(solve1(e, "(call((a(X), !)) ; X = 7)"), "[1, 7]");
}

TEST(SegbrainEngine, IfThenElseNegationOnce) {
  Engine e = with("a(1). a(2). t(X, Y) :- ( a(X) -> Y = yes ; Y = no ).");
  EXPECT_EQ(solve1(e, "t(2, X)"), "[yes]");
  EXPECT_EQ(solve1(e, "t(5, X)"), "[no]");
  EXPECT_EQ(solve1(e, "(a(Y) -> X = Y ; X = none)"), "[1]");
  EXPECT_EQ(solve1(e, "(\\+ a(3), X = ok)"), "[ok]");
  EXPECT_EQ(solve1(e, "(\\+ a(1), X = ok)"), "[]");
  EXPECT_EQ(solve1(e, "once(a(X))"), "[1]");
  EXPECT_EQ(solve1(e, "forall(a(Y), Y > 0), X = all"), "[all]");
}

TEST(SegbrainEngine, Arithmetic) {
  Engine e = with("");
  EXPECT_EQ(solve1(e, "X is 7 // 2"), "[3]");
  EXPECT_EQ(solve1(e, "X is 7 mod 3"), "[1]");
  EXPECT_EQ(solve1(e, "X is 2 + 3 * 4"), "[14]");
  EXPECT_EQ(solve1(e, "X is max(2, 5) - abs(-1)"), "[4]");
  EXPECT_EQ(solve1(e, "X is sqrt(16.0)"), "[4.0]");
  EXPECT_EQ(solve1(e, "sum_list([1, 2, 3], X)"), "[6]");
  EXPECT_EQ(solve1(e, "msort([c, a, b], X)"), "[[a, b, c]]");
  EXPECT_EQ(solve1(e, "length([a, b], X)"), "[2]");
  EXPECT_EQ(solve1(e, "nth0(1, [a, b, c], X)"), "[b]");
  EXPECT_EQ(solve1(e, "append(X, [c], [a, b, c])"), "[[a, b]]");
  EXPECT_THROW(solve1(e, "X is foo + 1"), fest::Error);
  EXPECT_THROW(solve1(e, "X is 1 // 0"), fest::Error);
}

TEST(SegbrainEngine, UnknownPredicateNamesTheCallingClause) {
  Engine e = with("ok.\ngoal :- ok,\n  missing_op(1).\n");
  try {
    e.prove(make_atom("goal"));
    FAIL() << "expected an error";
  } catch (const fest::Error& err) {
    EXPECT_EQ(err.status(), fest::Status::bad_input);
    EXPECT_NE(std::string(err.what()).find("t.pl:2"), std::string::npos) << err.what();
    EXPECT_NE(std::string(err.what()).find("missing_op/1"), std::string::npos) << err.what();
  }
  auto undefined = e.undefined_calls();
  ASSERT_EQ(undefined.size(), 1u);
  EXPECT_EQ(undefined[0].first, "missing_op/1");
}

TEST(SegbrainEngine, LimitsStopRunawayProofs) {
  Engine e = with("loop(X) :- Y is X + 1, loop(Y).");
  Limits l;
  l.max_inferences = 5000;
  e.set_limits(l);
  try {
    e.prove(parse_term("loop(0)", "g"));
    FAIL() << "expected a limit";
  } catch (const fest::Error& err) {
    EXPECT_EQ(err.status(), fest::Status::failure);
  }
  Engine d = with("deep(0) :- !.\ndeep(N) :- M is N - 1, deep(M), true.");
  Limits ld;
  ld.max_depth = 50;
  d.set_limits(ld);
  EXPECT_THROW(d.prove(parse_term("deep(100)", "g")), fest::Error);
  EXPECT_TRUE(d.prove(parse_term("deep(10)", "g")));
}

// Under the default limits a one-clause loop recursed until SIGSEGV (8 MiB stack, Release
// and ASan alike) before max_depth or max_inferences was reached: now a limit error.
TEST(SegbrainEngine, DeepRecursionStopsBeforeTheStackEnds) {
  Engine e = with("loop(X) :- Y is X + 1, loop(Y).");
  e.set_limits(Limits{});
  try {
    e.prove(parse_term("loop(0)", "g"));
    FAIL() << "expected a limit";
  } catch (const fest::Error& err) {
    EXPECT_EQ(err.status(), fest::Status::failure);
  }
}

TEST(SegbrainEngine, DynamicFactsPersistAcrossBacktracking) {
  Engine e = with(":- dynamic(seen/1).\nrecord :- member(X, [a, b]), assertz(seen(X)), fail.\nrecord.\n");
  EXPECT_TRUE(e.prove(make_atom("record")));
  EXPECT_EQ(solve1(e, "seen(X)"), "[a, b]");
  EXPECT_EQ(solve1(e, "retract(seen(a)), X = done"), "[done]");
  EXPECT_EQ(solve1(e, "seen(X)"), "[b]");
}

TEST(SegbrainEngine, WorkspaceObjectsReleasedOnBacktracking) {
  Grid g;
  g.n = {4, 4, 4};
  Workspace ws(g);
  Object img;
  img.image.assign(g.size(), 1.0f);
  ws.put_root("t1", img);
  Engine e = with(
      "try(T) :- threshold(t1, T, inf, m), T > 5.\n"
      "pick(T) :- member(T, [0, 2, 9]), threshold(t1, T, inf, m), volume_ml(m, V), V > 0.\n");
  ws.register_operators(e);
  const std::size_t before = ws.size();
  // Each failed candidate releases `m`, so the name can be reused by the next one.
  EXPECT_FALSE(e.prove(parse_term("member(T, [1, 2, 3]), try(T)", "g")));
  EXPECT_EQ(ws.size(), before);
  EXPECT_TRUE(e.prove(parse_term("pick(T)", "g")));
  EXPECT_EQ(ws.size(), before + 1);
  EXPECT_GT(e.counters().foreign_calls, 3u);
}

TEST(SegbrainEngine, OptionalRecordsSkippedGoals) {
  Engine e = with("g :- optional(fail), optional(true).");
  EXPECT_TRUE(e.prove(make_atom("g")));
  ASSERT_EQ(e.skipped().size(), 1u);
  EXPECT_EQ(e.skipped()[0], "fail");
}

TEST(SegbrainEngine, TraceMeasureOnOperatorExitsAndFailuresWithTheBound) {
  Grid g;
  g.n = {4, 4, 4};
  Workspace ws(g);
  Object img;
  img.image.assign(g.size(), 1.0f);
  ws.put_root("t1", img);
  Engine e = with(
      "check(M) :- volume_ml(M, V), V =< 0.01.\n"
      "g :- threshold(t1, 0, inf, m), check(m).\n");
  ws.register_operators(e);
  std::vector<TraceEvent> events;
  e.set_trace([&](const TraceEvent& ev) { events.push_back(ev); });
  EXPECT_FALSE(e.prove(make_atom("g")));
  bool exit_measured = false, fail_with_bound = false;
  for (const auto& ev : events) {
    const std::string port = ev.port;
    if (port == "call" || port == "redo") {
      EXPECT_TRUE(ev.measure.empty()) << ev.goal;
    }
    if (port == "exit" && ev.goal.rfind("volume_ml", 0) == 0)
      exit_measured = ev.measure.size() == 1 && ev.measure[0].first == "volume_ml" && ev.measure[0].second == 0.064;
    if (port == "fail" && ev.goal == "check(m)")
      for (const auto& [k, v] : ev.measure) fail_with_bound = fail_with_bound || (k == "max" && v == 0.01);
  }
  EXPECT_TRUE(exit_measured);
  EXPECT_TRUE(fail_with_bound);
  EXPECT_NE(e.last_failing_check().find("check (volume_ml 0.064"), std::string::npos) << e.last_failing_check();
}

// format_atom/3 (the knowledge base's notes on what it skipped, docs/segbrain.md §1):
// the text format/2 would log, as an atom; integers print without a decimal point.
TEST(SegbrainEngine, FormatAtomBuildsText) {
  Engine e = with("fov(66.4, 82.0, 49.6).");
  EXPECT_EQ(solve1(e, "fov(A, B, C), Ai is round(A), Bi is round(B), Ci is round(C), "
                      "format_atom('field of view ~wx~wx~w mm', [Ai, Bi, Ci], X)"),
            "['field of view 66x82x50 mm']");
  EXPECT_EQ(solve1(e, "format_atom('~w not sought: ~w', [brainstem, 'no ventricles'], X)"),
            "['brainstem not sought: no ventricles']");
  EXPECT_EQ(solve1(e, "format_atom(plain, [], X)"), "[plain]");
  // The format must be text.
  EXPECT_THROW(e.prove(parse_term("format_atom(42, [], _)", "goal")), fest::Error);
}
