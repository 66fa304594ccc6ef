// Tokenizer and operator-precedence parser of the rule language.
#include "segbrain/kb_parser.hpp"

#include <cctype>
#include <map>
#include <optional>

#include "core/error.hpp"
#include "core/text_position.hpp"
#include "segbrain/operators_table.hpp"

namespace fest::segbrain {
namespace {

enum class Tok { atom, var, integer, real, string, punct, end, eof };

struct Token {
  Tok kind = Tok::eof;
  std::string text;
  std::int64_t ival = 0;
  double fval = 0;
  int line = 1, col = 1;
  bool quoted = false;
  bool layout_before = false;  // whitespace precedes it ("foo (" is not a call)
};

const std::string kSymbolChars = "+-*/\\^<>=~:.?@#&$";

class Lexer {
 public:
  Lexer(const std::string& text, const std::string& file) : s_(text), file_(file) {}

  [[noreturn]] void error(int line, int col, const std::string& what) const {
    throw bad_input("{}:{}:{}: syntax error: {}", file_, line, col, what);
  }

  Token next() {
    Token t;
    t.layout_before = skip_layout();
    t.line = pos_.line;
    t.col = pos_.col;
    if (i_ >= s_.size()) {
      t.kind = Tok::eof;
      return t;
    }
    char c = s_[i_];
    if (std::isdigit(static_cast<unsigned char>(c))) return number(t);
    if (c == '_' || std::isupper(static_cast<unsigned char>(c))) {
      t.kind = Tok::var;
      while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) t.text += take();
      return t;
    }
    if (std::islower(static_cast<unsigned char>(c))) {
      t.kind = Tok::atom;
      while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) t.text += take();
      return t;
    }
    if (c == '\'') {
      t.kind = Tok::atom;
      t.quoted = true;
      t.text = quoted('\'', t);
      return t;
    }
    if (c == '"') {
      t.kind = Tok::string;
      t.text = quoted('"', t);
      return t;
    }
    if (c == '(' || c == ')' || c == '[' || c == ']' || c == ',' || c == '|' || c == '{' || c == '}') {
      t.kind = Tok::punct;
      t.text = take();
      return t;
    }
    if (c == '!' || c == ';') {
      t.kind = Tok::atom;
      t.text = take();
      return t;
    }
    if (c == '.' && (i_ + 1 >= s_.size() || std::isspace(static_cast<unsigned char>(s_[i_ + 1])) || s_[i_ + 1] == '%')) {
      take();
      t.kind = Tok::end;
      t.text = ".";
      return t;
    }
    if (kSymbolChars.find(c) != std::string::npos) {
      t.kind = Tok::atom;
      while (i_ < s_.size() && kSymbolChars.find(s_[i_]) != std::string::npos) t.text += take();
      return t;
    }
    error(t.line, t.col, std::string("unexpected character '") + c + "'");
  }

 private:
  char take() {
    char c = s_[i_++];
    pos_.advance(c);
    return c;
  }

  bool skip_layout() {
    bool any = false;
    while (i_ < s_.size()) {
      char c = s_[i_];
      if (std::isspace(static_cast<unsigned char>(c))) {
        take();
        any = true;
      } else if (c == '%') {
        while (i_ < s_.size() && s_[i_] != '\n') take();
        any = true;
      } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
        int l = pos_.line, cc = pos_.col;
        take();
        take();
        while (i_ + 1 < s_.size() && !(s_[i_] == '*' && s_[i_ + 1] == '/')) take();
        if (i_ + 1 >= s_.size()) error(l, cc, "unterminated block comment");
        take();
        take();
        any = true;
      } else {
        break;
      }
    }
    return any;
  }

  Token number(Token& t) {
    std::string d;
    while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) d += take();
    bool real = false;
    if (i_ + 1 < s_.size() && s_[i_] == '.' && std::isdigit(static_cast<unsigned char>(s_[i_ + 1]))) {
      real = true;
      d += take();
      while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) d += take();
    }
    if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      std::size_t j = i_ + 1;
      if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
      if (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) {
        real = true;
        while (i_ < j) d += take();
        while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) d += take();
      }
    }
    t.text = d;
    if (real) {
      t.kind = Tok::real;
      try {
        t.fval = std::stod(d);
      } catch (const std::exception&) {  // beyond double's range, or below it
        error(t.line, t.col, "number out of range");
      }
    } else {
      t.kind = Tok::integer;
      try {
        t.ival = std::stoll(d);
      } catch (const std::exception&) {
        error(t.line, t.col, "integer too large");
      }
    }
    return t;
  }

  std::string quoted(char q, const Token& t) {
    take();
    std::string out;
    while (true) {
      if (i_ >= s_.size()) error(t.line, t.col, "unterminated quoted text");
      char c = take();
      if (c == q) {
        if (i_ < s_.size() && s_[i_] == q) {  // doubled quote
          out += take();
          continue;
        }
        return out;
      }
      if (c == '\\' && i_ < s_.size()) {
        char e = take();
        out += e == 'n' ? '\n' : e == 't' ? '\t' : e;
        continue;
      }
      out += c;
    }
  }

  const std::string& s_;
  std::string file_;
  std::size_t i_ = 0;
  TextPosition pos_;
};

class Parser {
 public:
  Parser(const std::string& text, const std::string& file) : lex_(text, file), file_(file) { advance(); }

  bool at_eof() const { return tok_.kind == Tok::eof; }
  const Token& current() const { return tok_; }

  // One clause term up to its end token.
  Term clause(std::map<std::string, int>& var_uses) {
    vars_.clear();
    uses_ = &var_uses;
    Term t = parse(1200);
    if (tok_.kind != Tok::end) fail("operator expected before " + describe(tok_));
    advance();
    return t;
  }

  Term whole_term() {
    std::map<std::string, int> uses;
    uses_ = &uses;
    Term t = parse(1200);
    if (tok_.kind == Tok::end) advance();
    if (tok_.kind != Tok::eof) fail("unexpected " + describe(tok_));
    return t;
  }

  [[noreturn]] void fail(const std::string& what) const { lex_.error(tok_.line, tok_.col, what); }

 private:
  static std::string describe(const Token& t) {
    switch (t.kind) {
      case Tok::eof: return "end of file";
      case Tok::end: return "end of clause '.'";
      case Tok::var: return "variable " + t.text;
      case Tok::string: return "string";
      default: return "'" + t.text + "'";
    }
  }

  void advance() { tok_ = lex_.next(); }

  bool is_term_start() const {
    switch (tok_.kind) {
      case Tok::atom:
        return !infix_op(tok_.text) || prefix_op(tok_.text);
      case Tok::var:
      case Tok::integer:
      case Tok::real:
      case Tok::string: return true;
      case Tok::punct: return tok_.text == "(" || tok_.text == "[" || tok_.text == "{";
      default: return false;
    }
  }

  Term variable(const std::string& name) {
    if (name == "_") return make_var("_");
    ++(*uses_)[name];
    auto it = vars_.find(name);
    if (it != vars_.end()) return it->second;
    Term v = make_var(name);
    vars_.emplace(name, v);
    return v;
  }

  void expect(const char* punct) {
    if (tok_.kind != Tok::punct || tok_.text != punct) fail(std::string("expected '") + punct + "' but found " + describe(tok_));
    advance();
  }

  std::vector<Term> arguments() {
    std::vector<Term> args;
    advance();  // '('
    args.push_back(parse(999));
    while (tok_.kind == Tok::punct && tok_.text == ",") {
      advance();
      args.push_back(parse(999));
    }
    expect(")");
    return args;
  }

  Term primary(int max_prec, int& prec) {
    prec = 0;
    Token t = tok_;
    switch (t.kind) {
      case Tok::integer: advance(); return make_int(t.ival);
      case Tok::real: advance(); return make_real(t.fval);
      case Tok::string: advance(); return make_string(t.text);
      case Tok::var: advance(); return variable(t.text);
      case Tok::punct:
        if (t.text == "(") {
          advance();
          Term inner = parse(1200);
          expect(")");
          return inner;
        }
        if (t.text == "[") {
          advance();
          if (tok_.kind == Tok::punct && tok_.text == "]") {
            advance();
            return make_atom("[]");
          }
          std::vector<Term> items{parse(999)};
          while (tok_.kind == Tok::punct && tok_.text == ",") {
            advance();
            items.push_back(parse(999));
          }
          Term tail;
          if (tok_.kind == Tok::punct && tok_.text == "|") {
            advance();
            tail = parse(999);
          }
          expect("]");
          return make_list(items, tail);
        }
        fail("unexpected " + describe(t));
      case Tok::atom: break;
      default: fail("unexpected " + describe(t));
    }
    advance();
    const Token& nx = tok_;
    if (nx.kind == Tok::punct && nx.text == "(" && !nx.layout_before) return make_compound(t.text, arguments());
    if (t.text == "-" && !t.quoted && (nx.kind == Tok::integer || nx.kind == Tok::real) && !nx.layout_before) {
      Token n = nx;
      advance();
      return n.kind == Tok::integer ? make_int(-n.ival) : make_real(-n.fval);
    }
    if (!t.quoted) {
      if (const OpDef* op = prefix_op(t.text)) {
        if (is_term_start()) {
          int p = op->priority, ap = op->type == OpType::fy ? p : p - 1;
          if (p > max_prec) {
            p = 999;
            ap = 999;
          }
          Term arg = parse(ap);
          prec = p;
          return make_compound(t.text, {arg});
        }
      }
    }
    return make_atom(t.text);
  }

  Term parse(int max_prec) {
    int left_prec = 0;
    Term left = primary(max_prec, left_prec);
    while (true) {
      std::string name;
      if (tok_.kind == Tok::atom && !tok_.quoted) name = tok_.text;
      else if (tok_.kind == Tok::punct && tok_.text == ",") name = ",";
      else if (tok_.kind == Tok::punct && tok_.text == "|") name = ";";  // '|' as disjunction
      else break;
      const OpDef* op = infix_op(name);
      if (!op || op->priority > max_prec) break;
      int lmax = op->type == OpType::yfx ? op->priority : op->priority - 1;
      int rmax = op->type == OpType::xfy ? op->priority : op->priority - 1;
      if (left_prec > lmax) break;
      advance();
      Term right = parse(rmax);
      left = make_compound(name, {left, right});
      left_prec = op->priority;
    }
    return left;
  }

  Lexer lex_;
  std::string file_;
  Token tok_;
  std::map<std::string, Term> vars_;
  std::map<std::string, int>* uses_ = nullptr;
};

}  // namespace

Program parse_program(const std::string& text, const std::string& file) {
  Program prog;
  Parser p(text, file);
  while (!p.at_eof()) {
    int line = p.current().line, col = p.current().col;
    std::map<std::string, int> uses;
    Term t = deref(p.clause(uses));
    if (t->kind == Kind::compound && t->name == ":-" && t->args.size() == 1) {
      prog.directives.push_back({t->args[0], file, line});
      continue;
    }
    Clause c;
    c.file = file;
    c.line = line;
    c.col = col;
    if (t->kind == Kind::compound && t->name == ":-" && t->args.size() == 2) {
      c.head = deref(t->args[0]);
      c.body = t->args[1];
    } else {
      c.head = t;
      c.body = make_atom("true");
    }
    if (!is_callable(c.head))
      throw bad_input("{}:{}:{}: syntax error: clause head is not an atom or compound", file, line, col);
    for (const auto& [name, n] : uses)
      if (n == 1 && name[0] != '_') c.singletons.push_back(name);
    prog.clauses.push_back(std::move(c));
  }
  return prog;
}

Term parse_term(const std::string& text, const std::string& where) {
  Parser p(text, where);
  return p.whole_term();
}

}  // namespace fest::segbrain
