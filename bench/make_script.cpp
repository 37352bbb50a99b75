// Writes one generated script (script_generators.hpp) to standard output, to measure the fapc
// program on it from outside: make_script KIND ELEMENTS > x.EXT; /usr/bin/time -v fapc compile x.EXT ...
// KIND: mimic, fml, xmto, xmto-to.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "script_generators.hpp"

int main(int argc, char** argv) {
  fapc::bench::ScriptKind kind{};
  if (argc != 3 || !fapc::bench::parse_script_kind(argv[1], kind)) {
    std::fprintf(stderr, "usage: make_script mimic|fml|xmto|xmto-to ELEMENTS\n");
    return 2;
  }
  const std::string text = fapc::bench::generate_script(kind, std::strtoull(argv[2], nullptr, 10));
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}
