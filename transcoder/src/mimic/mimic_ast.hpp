// Private: the Mimic program as parsed (Mimic Table 1), before any checking beyond the grammar.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fapc::mimic {

struct Position {
  int line = 0;
  int column = 0;
};

struct Number {
  double value = 0;
  Position at;
};

// The pname / pname-arg keywords of Mimic Table 1, as a byte: a program has millions of them.
enum class ParamName : std::uint8_t {
  left,
  right,
  connect,  // a value or none
  in,
  hold,
  out,
  value,
  duration,
  freq,
  period,
  min,
  max,  // a value
  linear,
  sin,
  log,
  exp,
  average,
  add,
  overwrite,  // no value
};
std::string_view to_string(ParamName name);
std::optional<ParamName> param_name(std::string_view text);  // empty: not a parameter

struct Param {
  ParamName id = ParamName::left;
  Position at;
  std::optional<Number> value;  // `name = 3.5`

  std::string name() const { return std::string(to_string(id)); }
};

struct Action {
  enum class Kind { sequence, parallel, named };
  Kind kind = Kind::named;
  Position at;
  std::vector<Param> params;
  // named: a parameter, a def or a defxpr name
  std::string name;
  bool has_list = false;  // `name ( times ; values ; )`
  std::vector<Number> times;
  std::vector<Number> values;
  Position list_at;
  // sequence / parallel
  std::vector<Action> children;
};

struct Definition {
  bool expression = false;  // defxpr
  std::string name;
  Position at;
  Action group;      // def
  std::string file;  // defxpr
  Position file_at;
};

// What the parser keeps: main's own actions go to a MainSink as they are read (mimic_parser.hpp).
struct Program {
  std::vector<Definition> definitions;
  std::vector<Param> main_params;
};

}  // namespace fapc::mimic
