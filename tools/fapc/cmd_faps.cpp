// fapc faps [--json]: the 68 face animation parameters, from fapcodec's table (fap_table.hpp),
// never a copy of it: number, name, unit, group, direction, legal range and quantiser step.
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "fapc/args.hpp"
#include "fapc/codec/fap_table.hpp"
#include "fapc/commands.hpp"

namespace fapc::cli {

namespace {

int run_faps(const std::vector<std::string>& argv) {
  Args args("faps", argv);
  if (!args.ok()) return usage_error("faps", args);
  if (!args.positionals().empty()) return usage_error("faps", codes::cli::operands, "takes no operands");
  if (args.flag("json")) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const FapInfo& f : fap_table()) {
      // FAP 1 and 2 are viseme and expression fields (0..63 each); the others' legal range is
      // symmetric even when unidirectional, as the reference codec treats them (docs/fap-table.md).
      const bool ranged = f.number > 2;
      out.push_back({{"number", f.number},
                     {"name", f.name},
                     {"unit", fapu_name(f.unit)},
                     {"group", f.group},
                     {"bidirectional", f.bidirectional},
                     {"positive_motion", f.positive_motion},
                     {"legal_min", ranged ? -f.legal_max() : 0},
                     {"legal_max", ranged ? f.legal_max() : 63},
                     {"quant_step", f.quant_step}});
    }
    std::cout << out.dump(2) << '\n';
    return kExitOk;
  }
  std::cout << std::left << std::setw(4) << "FAP" << std::setw(26) << "name" << std::setw(7) << "unit" << std::setw(7)
            << "group" << std::setw(5) << "dir" << std::setw(16) << "legal range"
            << "step  positive motion\n";
  for (const FapInfo& f : fap_table()) {
    // Symmetric even for unidirectional FAPs, as the reference codec treats them (docs/fap-table.md).
    const std::string range =
        f.number <= 2 ? "0..63" : std::to_string(-f.legal_max()) + ".." + std::to_string(f.legal_max());
    std::cout << std::left << std::setw(4) << f.number << std::setw(26) << f.name << std::setw(7) << fapu_name(f.unit)
              << std::setw(7) << f.group << std::setw(5) << (f.bidirectional ? "B" : "U") << std::setw(16) << range
              << std::setw(6) << f.quant_step << f.positive_motion << '\n';
  }
  return kExitOk;
}

const RegisterCommand faps_command{"faps", run_faps};

}  // namespace

}  // namespace fapc::cli
