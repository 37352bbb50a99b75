// Private: recursive descent over the grammar of Mimic Table 1 (docs/mimic.md, "Grammar").
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "mimic_ast.hpp"

namespace fapc::mimic {

// Receives main's actions as they are parsed, so that a program of a million actions is never held
// as a tree: first the definitions (kept whole, as macros expand from them) and main's
// parameters, then main's groups opened and closed around their named actions, in source order.
// A syntax error anywhere still stops the parse: the sink's findings count only when it ends well.
class MainSink {
 public:
  virtual ~MainSink() = default;
  virtual void begin_main(const std::vector<Definition>& definitions, const std::vector<Param>& main_params) = 0;
  virtual void open_group(const Action& group) = 0;  // kind, position and parameters; no children
  virtual void named_action(Action&& action) = 0;
  virtual void close_group() = 0;
};

// Parses into `program` (its definitions and main's parameters; Program::main stays empty) and
// hands main to `sink` as it goes. `program` must not move while the sink may look at it.
Status parse_program(std::string_view source, const std::string& file_name, Program& program, MainSink& sink);

}  // namespace fapc::mimic
