// Private: the Mimic program as parsed (Mimic Table 1), before any checking beyond the grammar.
#pragma once

#include <optional>
#include <string>
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

struct Param {
  std::string name;  // one of the pname / pname-arg keywords
  Position at;
  std::optional<Number> value;  // `name = 3.5`
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
  Action group;       // def
  std::string file;   // defxpr
  Position file_at;
};

// What the parser keeps: main's own actions go to a MainSink as they are read (mimic_parser.hpp).
struct Program {
  std::vector<Definition> definitions;
  std::vector<Param> main_params;
};

}  // namespace fapc::mimic
