// compile_one IN OUT: any input fapc reads to any output it writes, kinds by extension, as
// `fapc compile IN -o OUT` does: warnings and the error printed, exit status 1 on failure.
#include <cstdio>

#include "fapc/pipeline/convert.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: compile_one INPUT OUTPUT\n");
    return 2;
  }
  const fapc::pipeline::ConvertResult result =
      fapc::pipeline::convert(argv[1], {{.path = argv[2], .kind = ""}}, fapc::pipeline::ConvertOptions{});
  for (const fapc::Diagnostic& warning : result.warnings)
    std::fprintf(stderr, "%s\n", fapc::format_diagnostic(warning).c_str());
  if (!result.ok()) {
    std::fprintf(stderr, "%s\n", fapc::format_diagnostic(*result.error).c_str());
    return 1;
  }
  return 0;
}
