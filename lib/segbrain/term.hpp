#pragma once
// Terms of the knowledge-base language (a Prolog subset, docs/segbrain.md §2, segbrain-rules(5)).
// A term is a shared node; variables are nodes whose `ref` is set while bound, and the
// engine's trail unsets them on backtracking, so terms never need copying to undo.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace fest::segbrain {

struct Node;
using Term = std::shared_ptr<Node>;

enum class Kind { var, atom, integer, real, string, compound };

struct Node {
  Kind kind = Kind::atom;
  std::string name;            // atom text, functor, string contents, variable name
  std::int64_t ival = 0;       // integer value; a variable's serial number
  double fval = 0;             // real value
  std::vector<Term> args;      // compound arguments
  Term ref;                    // binding of a variable (null while free)
};

Term make_var(const std::string& name = "_");
Term make_atom(const std::string& name);
Term make_int(std::int64_t v);
Term make_real(double v);
Term make_string(const std::string& s);
Term make_compound(const std::string& functor, std::vector<Term> args);
Term make_list(const std::vector<Term>& items, Term tail = nullptr);

// Follows variable bindings to the representative term.
Term deref(Term t);

bool is_atom(const Term& t, const char* name);   // t (dereferenced) is that atom
bool is_callable(const Term& t);
bool is_number(const Term& t);
double number_value(const Term& t);               // integer or real, dereferenced
// "name/arity" of an atom or compound.
std::string indicator(const Term& t);

// Elements of a proper list; returns false when t is not one (partial or improper).
bool list_items(Term t, std::vector<Term>& items);

// Prints a term with its current bindings, operators written infix where they are
// operators of the language, so the output reads back as the same term.
std::string to_string(const Term& t);

// A copy with fresh variables (bindings resolved); `vars` maps old to new variables.
Term copy_term(const Term& t);

// Standard order of terms: var < number < atom < string < compound.
int compare_terms(const Term& a, const Term& b);

}  // namespace fest::segbrain
