#pragma once
// The operator table of the rule language (standard Prolog priorities, segbrain-rules(5)),
// shared by the parser and the printer so printed terms parse back identically.

#include <string>

namespace fest::segbrain {

enum class OpType { xfx, xfy, yfx, fy, fx };

struct OpDef {
  int priority;
  OpType type;
};

// The infix definition of `name`, or null.
const OpDef* infix_op(const std::string& name);
// The prefix definition of `name`, or null.
const OpDef* prefix_op(const std::string& name);

}  // namespace fest::segbrain
