// The options' declaration (tools/fapc/cli_spec.cpp) against the pipeline's rows
// (tools/pipeline/src/registry.cpp), which say the options each kind reads or writes: a row names
// only declared options of the right role, every option that changes how inputs are read (or
// outputs written) is named by some row, and the rows that hand their documents to others name
// what those read. The numbers' ranges and defaults are checked where people see them.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "fapc/cli_spec.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/pipeline/registry.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

using cli::OptionRole;
using cli::OptionSpec;

// Every option some row of `table` names, with the kinds that name it.
template <class Format>
std::map<std::string, std::vector<std::string>> named_by(const std::vector<Format>& table) {
  std::map<std::string, std::vector<std::string>> out;
  for (const Format& f : table)
    for (const std::string& o : f.options) out[o].push_back(f.kind);
  return out;
}

TEST(OptionRows, RowsNameDeclaredOptionsOfTheirRole) {
  const auto& formats = pipeline::formats();
  for (const auto& [name, kinds] : named_by(formats.inputs())) {
    const OptionSpec* spec = cli::find_option(name);
    ASSERT_NE(spec, nullptr) << "--" << name << " (named by " << kinds.front() << ") is not declared";
    EXPECT_EQ(spec->role, OptionRole::reading) << "--" << name << " is named by the input row " << kinds.front();
    // compile reads every kind: an option an input row names must reach it.
    EXPECT_TRUE(spec->applies_to("compile")) << "--" << name;
  }
  for (const auto& [name, kinds] : named_by(formats.outputs())) {
    const OptionSpec* spec = cli::find_option(name);
    ASSERT_NE(spec, nullptr) << "--" << name << " (named by " << kinds.front() << ") is not declared";
    // An output made while reading (the voice of a .wav) may name an option of the reading.
    EXPECT_NE(spec->role, OptionRole::command) << "--" << name << " is named by the output row " << kinds.front();
    EXPECT_TRUE(spec->applies_to("compile")) << "--" << name;
  }
}

TEST(OptionRows, EveryReadingOrWritingOptionIsNamedByARow) {
  const auto inputs = named_by(pipeline::formats().inputs());
  const auto outputs = named_by(pipeline::formats().outputs());
  int reading = 0;
  for (const OptionSpec& o : cli::option_specs()) {
    const std::string name(o.name);
    if (o.role == OptionRole::reading) {
      ++reading;
      EXPECT_TRUE(inputs.count(name)) << "--" << name << " changes how inputs are read, but no input row names it";
    }
    if (o.role == OptionRole::writing) {
      EXPECT_TRUE(outputs.count(name)) << "--" << name << " changes what is written, but no output row names it";
    }
  }
  EXPECT_GE(reading, 10);  // lexicon, voice, event, speech-rate, fps, the limits...
}

// The .xml row hands a document to the row naming its root, and a .combine reads its operands as
// whatever they are: each names every option of the rows it reads through.
TEST(OptionRows, RowsReadingThroughOthersNameTheirOptions) {
  const auto& formats = pipeline::formats();
  const pipeline::InputFormat* xml = formats.input_for("x.xml");
  const pipeline::InputFormat* combine = formats.input_for("x.combine");
  ASSERT_NE(xml, nullptr);
  ASSERT_NE(combine, nullptr);
  const auto names = [](const pipeline::InputFormat& f, const std::string& option) {
    return std::find(f.options.begin(), f.options.end(), option) != f.options.end();
  };
  for (const pipeline::InputFormat& f : formats.inputs()) {
    for (const std::string& option : f.options) {
      if (!f.xml_roots.empty()) {
        EXPECT_TRUE(names(*xml, option)) << f.kind << " names --" << option;
      }
      EXPECT_TRUE(names(*combine, option)) << f.kind << " names --" << option;
    }
  }
}

// The declaration gives the parser's range: one below it is refused with the range named, and
// help shows it. Checked through the program (a usage error comes before any file is read), on
// two options of each kind of number.
TEST(OptionRows, NumbersAreReadWithinTheirDeclaredRange) {
  for (const char* name : {"fps", "quant", "speech-rate", "max-speech-seconds"}) {
    const OptionSpec* spec = cli::find_option(name);
    ASSERT_NE(spec, nullptr);
    ASSERT_NE(spec->numeric, cli::Numeric::none) << name;
    const std::string low = cli::shown_number(spec->low, spec->numeric);
    const std::string high = cli::shown_number(spec->high, spec->numeric);
    const std::string below = cli::shown_number(spec->low - 1, spec->numeric);
    const test::CommandRun run =
        test::run_fapc("compile absent.mimic -o absent.fap --" + std::string(name) + " " + below);
    EXPECT_EQ(run.exit_status, 2) << name;
    const std::string kind = spec->numeric == cli::Numeric::integer ? "an integer" : "a number";
    EXPECT_NE(run.err.find("--" + std::string(name) + " takes " + kind + " from " + low + " to " + high + ", not '" +
                           below + "'"),
              std::string::npos)
        << run.err;
    const test::CommandRun help = test::run_fapc("compile --help");
    EXPECT_NE(help.out.find("from " + low), std::string::npos) << name;
  }
}

// An option no row of the conversion names (--lexicon to a .fap) draws a warning with a code and
// changes nothing; --strict refuses; an option the input's kind reads draws none.
TEST(OptionRows, AnOptionTheInputsKindDoesNotReadIsWarnedOf) {
  const std::string out = test::scratch_folder("option-rows");
  const std::string fap = "corpus/examples/fap/joy.fap";
  const test::CommandRun warned = test::run_fapc("compile " + fap + " -o " + out + "/joy.fba --lexicon absent.json -v");
  EXPECT_EQ(warned.exit_status, 0) << warned.err;
  EXPECT_NE(warned.err.find(fap + ": warning[format.option_not_read]: --lexicon changes nothing here: fap inputs do "
                                  "not read it ("),
            std::string::npos)
      << warned.err;
  const test::CommandRun plain = test::run_fapc("compile " + fap + " -o " + out + "/plain.fba");
  EXPECT_EQ(plain.exit_status, 0) << plain.err;
  EXPECT_EQ(test::read_text(out + "/joy.fba"), test::read_text(out + "/plain.fba"));

  const test::CommandRun strict = test::run_fapc("compile " + fap + " -o " + out + "/strict.fba --event a=b --strict");
  EXPECT_EQ(strict.exit_status, 1);
  EXPECT_NE(strict.err.find("--event changes nothing here"), std::string::npos) << strict.err;
  EXPECT_FALSE(std::filesystem::exists(out + "/strict.fba"));

  // A kind that reads it draws nothing.
  const test::CommandRun read =
      test::run_fapc("compile corpus/examples/mimic/figure3.mimic -o " + out + "/figure3.fap --fps 30 --duration 2");
  EXPECT_EQ(read.exit_status, 0) << read.err;
  EXPECT_EQ(read.err.find("changes nothing"), std::string::npos) << read.err;
}

// The defaults people read are the libraries' own.
TEST(OptionRows, DefaultsAreTheLibrariesOwn) {
  EXPECT_EQ(cli::find_option("fps")->shown_default, std::to_string(pipeline::ConvertOptions{}.fps));
  EXPECT_EQ(cli::find_option("max-frames")->shown_default, std::to_string(Limits{}.max_frames));
  EXPECT_EQ(cli::find_option("max-speech-seconds")->shown_default, "1800");
  EXPECT_EQ(cli::find_option("speech-rate")->shown_default, "175");
  EXPECT_EQ(cli::find_option("size")->shown_default, "640x480");
  EXPECT_EQ(cli::find_option("ranges")->value_facts(), "one of fit, max; default fit");
}

}  // namespace
}  // namespace fapc
