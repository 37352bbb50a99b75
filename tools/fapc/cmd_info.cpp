// fapc info FILE [--json]: what a file holds (fapc::pipeline::describe), as text or JSON.
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "fapc/args.hpp"
#include "fapc/commands.hpp"
#include "fapc/options.hpp"
#include "fapc/pipeline/info.hpp"
#include "fapc/pipeline/json_access.hpp"
#include "fapc/pipeline/json_output.hpp"
#include "fapc/report.hpp"
#include "fapc/streams.hpp"

namespace fapc::cli {

namespace {

// "header_name" -> "header name": the text output keeps words apart as before the JSON keys
// became snake_case (docs/json.md).
std::string key_text(std::string key) {
  for (char& c : key)
    if (c == '_') c = ' ';
  return key == "fap quant" ? "fap_quant" : key;
}

std::string scalar_text(const nlohmann::ordered_json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_null()) return "none";
  if (v.is_object() && v.contains("intra_min")) {  // a quantised range: "open_jaw I -1..1 P -2..2"
    return v["name"].get<std::string>() + " I " + v["intra_min"].dump() + ".." + v["intra_max"].dump() + " P " +
           v["predictive_min"].dump() + ".." + v["predictive_max"].dump();
  }
  if (v.is_object()) {
    std::string out;
    for (const auto& [k, item] : v.items()) out += (out.empty() ? "" : ", ") + key_text(k) + " " + scalar_text(item);
    return out.empty() ? "none" : out;
  }
  if (v.is_array()) {
    std::string out;
    for (const auto& item : v) out += (out.empty() ? "" : ", ") + scalar_text(item);
    return out.empty() ? "none" : out;
  }
  if (v.is_number_float()) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(3) << v.get<double>();
    return s.str();
  }
  return v.dump();
}

void print_text(const nlohmann::ordered_json& info) {
  for (const auto& [key, value] : info.items()) {
    if (key == "faps" || key == "warnings") continue;
    if (value.is_object()) {
      std::cout << key_text(key) << ":\n";
      for (const auto& [k, v] : value.items()) {
        if (v.is_object() && !v.empty()) {  // names to values (FML events, XMT-Omega meta): one line each
          for (const auto& [name, text] : v.items())
            std::cout << "  " << key_text(k) << " " << name << ": " << scalar_text(text) << '\n';
        } else {
          std::cout << "  " << key_text(k) << ": " << scalar_text(v) << '\n';
        }
      }
    } else if (key != "schema_version") {
      std::cout << key_text(key) << ": " << scalar_text(value) << '\n';
    }
  }
  for (const auto& f : info["faps"]) {
    std::cout << "  " << std::left << std::setw(4) << f["number"].get<int>() << std::setw(24)
              << f["name"].get<std::string>() << std::setw(6) << f["unit"].get<std::string>()
              << f["min"].get<long long>() << " .. " << f["max"].get<long long>() << " in "
              << f["frames"].get<long long>() << " frames\n";
  }
  std::cout << "warnings: " << info["warnings"].size() << '\n';
  for (const auto& w : info["warnings"]) std::cout << "  " << w["text"].get<std::string>() << '\n';
}

int run_info(const std::vector<std::string>& argv) {
  Args args("info", argv);
  ConvertOptions parsed = convert_options(args);
  if (!args.ok()) return usage_error("info", args);
  if (args.positionals().size() != 1) return usage_error("info", codes::cli::operands, "expected one FILE");
  std::string input = args.positionals().front();
  StandardInputCopy copy;
  if (const auto error = resolve_input(args, input, parsed, copy))
    return usage_error("info", codes::cli::standard_input, *error);
  auto info = pipeline::describe(input, parsed.limits, parsed.input_kind);
  if (!info) {
    if (args.flag("json")) std::cout << pipeline::error_document(info.error()).dump(2) << '\n';
    return report_outcome({}, info.error());
  }
  if (input != args.positionals().front()) json_of(*info)["file"] = args.positionals().front();  // not the copy's name
  if (args.flag("json")) {
    std::cout << info->dump(2) << '\n';
  } else {
    print_text(json_of(*info));
  }
  return kExitOk;
}

const RegisterCommand info_command{"info", run_info};

}  // namespace

}  // namespace fapc::cli
