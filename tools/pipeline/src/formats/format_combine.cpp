// .combine inputs: a file holding one Algebra expression (docs/algebra.md), operands relative to
// the file's folder; `#` lines are comments. Lets batch runs and compositions use combinations.
#include <filesystem>

#include "fapc/codec/file_io.hpp"
#include "fapc/pipeline/codes.hpp"
#include "fapc/pipeline/combine.hpp"
#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<Loaded> load_combine(const std::string& path, const ConvertOptions& options) {
  Result<std::string> text = read_file_bytes(path, options.limits);
  if (!text) return text.error();
  // The expression is the text without comment lines; errors point into the file.
  std::string expression;
  int line_number = 0;
  int expression_line = 0;
  std::size_t start = 0;
  while (start <= text->size()) {
    const std::size_t end = std::min(text->find('\n', start), text->size());
    std::string line = text->substr(start, end - start);
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") != std::string::npos && line[line.find_first_not_of(" \t")] != '#') {
      if (!expression.empty()) {
        return make_error(codes::combine::two_expressions, Location::text(path, line_number, 1),
                          "a .combine file holds one expression on one line", line);
      }
      expression = line;
      expression_line = line_number;
    }
    start = end + 1;
  }
  if (expression.empty())
    return make_error(codes::combine::no_expression, Location::text(path, 1, 1), "no expression in this file");
  Loaded loaded;
  Result<algebra::Value> value = evaluate_combination(expression, path, options, loaded.warnings);
  if (!value) {
    Diagnostic d = value.error();
    if (d.where.file == "<expression>") d.where = Location::text(path, expression_line, d.where.column);
    return d;
  }
  loaded.frames = frames_of(*value, options.fps, std::filesystem::path(path).stem().string());
  return loaded;
}

}  // namespace

InputFormat combine_input() { return {"combine", {".combine"}, load_combine}; }

}  // namespace fapc::pipeline::builtin
