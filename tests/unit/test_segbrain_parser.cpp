// KB parser (docs/segbrain.md §2, segbrain-rules(5)): round trip parse -> print -> parse, and syntax errors with
// the right file:line:col.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "segbrain/kb_parser.hpp"
#include "testdata.hpp"

#include <filesystem>
#include <map>
#include <regex>

using namespace fest::segbrain;

namespace {

// Printed variables carry addresses; numbering them by first appearance makes two
// prints of the same clause comparable.
std::string normalise(const std::string& s) {
  std::regex var("_G[0-9]+");
  std::map<std::string, int> ids;
  std::string out;
  auto begin = std::sregex_iterator(s.begin(), s.end(), var);
  std::size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    out += s.substr(last, it->position() - last);
    auto [pos, fresh] = ids.emplace(it->str(), int(ids.size()));
    out += "V" + std::to_string(pos->second);
    last = it->position() + it->length();
  }
  return out + s.substr(last);
}

std::string error_of(const std::string& text) {
  try {
    parse_program(text, "kb.pl");
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SegbrainParser, RoundTrip) {
  const std::string text =
      "% comment\n"
      "find(X) :- candidates(w, Ws), member((A, B), Ws), Lo is A * 2 - -1, \\+ bad(Lo), !.\n"
      "t(\"a string\", 'Quoted atom', [1, 2.5 | T], T, -3, - x, 1.0e-3).\n"
      "c(X) :- ( X > 1 -> Y = a ; Y = b ), call(p, Y). /* block */\n"
      "ops(X) :- X =:= 2 ** 3 // 4 mod 5, X =\\= 1, X \\== y.\n";
  Program p = parse_program(text, "kb.pl");
  ASSERT_EQ(p.clauses.size(), 4u);
  EXPECT_EQ(p.clauses[1].line, 3);
  for (const auto& c : p.clauses) {
    std::string printed = to_string(make_compound(":-", {c.head, c.body})) + ".";
    Program q = parse_program(printed, "again.pl");
    ASSERT_EQ(q.clauses.size(), 1u) << printed;
    EXPECT_EQ(normalise(to_string(make_compound(":-", {q.clauses[0].head, q.clauses[0].body})) + "."), normalise(printed));
  }
  // Operator priorities: a - b - c is (a - b) - c; a , b , c nests to the right.
  EXPECT_EQ(to_string(parse_term("a - b - c", "t")), "a - b - c");
  Term t = deref(parse_term("a - b - c", "t"));
  EXPECT_EQ(to_string(t->args[0]), "a - b");
  EXPECT_EQ(to_string(parse_term("a - (b - c)", "t")), "a - (b - c)");
  EXPECT_EQ(to_string(parse_term("2 * (3 + 4)", "t")), "2 * (3 + 4)");
}

TEST(SegbrainParser, SyntaxErrorsCarryLineAndColumn) {
  EXPECT_NE(error_of("ok.\nbad(X :- true.\n").find("kb.pl:2:7:"), std::string::npos) << error_of("ok.\nbad(X :- true.\n");
  EXPECT_NE(error_of("a.\n\n  b c.\n").find("kb.pl:3:5:"), std::string::npos) << error_of("a.\n\n  b c.\n");
  EXPECT_NE(error_of("a :- 'open.\n").find("kb.pl:1:6:"), std::string::npos);
  EXPECT_NE(error_of("a :- b").find("syntax error"), std::string::npos);
  EXPECT_NE(error_of("/* never closed\n").find("kb.pl:1:1:"), std::string::npos);
  EXPECT_NE(error_of("3 :- b.\n").find("clause head"), std::string::npos);
}

TEST(SegbrainParser, DirectivesAndSingletons) {
  Program p = parse_program(":- include('more.pl').\n:- dynamic(seen/1).\nf(X, Y, _Z) :- g(X).\n", "kb.pl");
  ASSERT_EQ(p.directives.size(), 2u);
  EXPECT_EQ(to_string(p.directives[0].goal), "include('more.pl')");
  ASSERT_EQ(p.clauses.size(), 1u);
  ASSERT_EQ(p.clauses[0].singletons.size(), 1u);
  EXPECT_EQ(p.clauses[0].singletons[0], "Y");
}

// A real number beyond double's range (found by fuzz_segbrain_kb) is a syntax error at
// its position, not an escaping std::out_of_range.
TEST(SegbrainParser, RealOutOfRangeIsASyntaxError) {
  for (const char* text : {"x(1.5e999).", "x(2E6666666666660.", "x(1e-999)."}) {
    SCOPED_TRACE(text);
    try {
      parse_program(text, "big.pl");
      ADD_FAILURE() << "no error";
    } catch (const fest::Error& e) {
      EXPECT_EQ(e.status(), fest::Status::bad_input);
      EXPECT_NE(std::string(e.what()).find("big.pl:1:3: syntax error: number out of range"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(parse_term("1.5e999", "goal"), fest::Error);
}

// Inputs that once crashed the reader (fuzz_segbrain_kb; tests/data/regress/segbrain/):
// each must now end in a clean fest::Error, as a rule file and as a single term.
TEST(SegbrainParser, RegressionInputs) {
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(fest::test::fixture("regress/segbrain"))) {
    SCOPED_TRACE(entry.path().filename().string());
    const std::string text = fest::test::slurp(entry.path().string());
    EXPECT_THROW(parse_program(text, "regress.pl"), fest::Error);
    EXPECT_THROW(parse_term(text, "regress"), fest::Error);
    ++replayed;
  }
  EXPECT_GE(replayed, 1);
}
