// The JSON contract (docs/json.md): real outputs of `info --json`, `verify --json`,
// `batch --report-json` and errors under --json, validated against docs/json/*.schema.json; every
// key of the schemas is documented in docs/json.md; and the validator itself rejects what it must.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "json_schema.hpp"
#include "support/test_support.hpp"

namespace fapc {
namespace {

test::SchemaFolder schemas() { return test::SchemaFolder(test::source_dir() + "/docs/json"); }

std::string joined(const std::vector<std::string>& problems) {
  std::string out;
  for (const std::string& p : problems) out += p + "\n";
  return out;
}

nlohmann::json run_json(const std::string& args, int expected_status) {
  const test::CommandRun run = test::run_fapc(args);
  EXPECT_EQ(run.exit_status, expected_status) << args << "\n" << run.err;
  return nlohmann::json::parse(run.out);
}

// Every kind of input info reads, the examples and the corpus's own folders.
TEST(JsonContract, InfoOfEveryInputKindMatchesItsSchema) {
  auto folder = schemas();
  // An .mp4 of fapc's own (the corpus's GPAC file carries planes fapc refuses).
  const std::string mp4 = test::binary_dir() + "/json-contract-joy.mp4";
  ASSERT_EQ(test::run_fapc("compile corpus/examples/fap/joy.fap -o '" + mp4 + "'").exit_status, 0);
  std::vector<std::string> inputs = {
      mp4};  // (.combine: its operands lie outside its folder, which info does not allow)
  for (const std::string dir :
       {"examples/fap", "examples/fml", "examples/mimic", "examples/xmto", "fba", "mp4", "xmto"})
    for (const std::string ext : {".fap", ".fba", ".mp4", ".fml", ".mimic", ".xmt"})
      for (const std::string& file : test::files_under(test::corpus_dir() + "/" + dir, ext))
        inputs.push_back(std::filesystem::relative(file, test::source_dir()).string());
  std::set<std::string> kinds;
  for (const std::string& input : inputs) {
    const test::CommandRun run = test::run_fapc("info '" + input + "' --json");
    if (run.exit_status != 0) continue;  // a corpus file that needs options of its own
    const nlohmann::json info = nlohmann::json::parse(run.out);
    EXPECT_EQ(joined(folder.validate(info, "info.schema.json")), "") << input;
    kinds.insert(info["kind"].get<std::string>());
    // The figures are the text output's, as numbers.
    EXPECT_EQ(info["faps_used"], info["faps"].size()) << input;
  }
  EXPECT_EQ(kinds, (std::set<std::string>{"fap", "fba", "fml", "mimic", "mp4", "xmt"}));
}

TEST(JsonContract, ErrorsUnderJsonAreADiagnosticObject) {
  auto folder = schemas();
  const nlohmann::json missing = run_json("info corpus/no-such-file.fap --json", 1);
  EXPECT_EQ(joined(folder.validate(missing, "error.schema.json")), "");
  EXPECT_EQ(missing["error"]["kind"], "io");
  EXPECT_EQ(missing["error"]["code"], "io.cannot_open");
  const nlohmann::json truncated = run_json("info corpus/fba-bad/truncated.fba --json", 1);
  EXPECT_EQ(joined(folder.validate(truncated, "error.schema.json")), "");
  EXPECT_TRUE(truncated["error"]["byte"].is_number_integer()) << truncated.dump();
  EXPECT_EQ(truncated["error"]["code"], "fba.truncated");
}

TEST(JsonContract, VerifyMatchesItsSchema) {
  auto folder = schemas();
  const nlohmann::json verified =
      run_json("verify corpus/examples/fap/joy.fap corpus/fba/vreng-joy.fba corpus/fba-bad/truncated.fba --json", 1);
  EXPECT_EQ(joined(folder.validate(verified, "verify.schema.json")), "");
  ASSERT_EQ(verified["files"].size(), 3u);
  const nlohmann::json& joy = verified["files"][0];
  EXPECT_EQ(joy["frames"], 108);  // `fapc info corpus/examples/fap/joy.fap`: 108 frames
  // bits_per_frame is the byte count's: 8 * bytes / frames.
  EXPECT_NEAR(joy["bits_per_frame"].get<double>(), 8.0 * joy["bytes"].get<double>() / 108, 1e-9);
  EXPECT_FALSE(verified["files"][2]["ok"]);
  EXPECT_EQ(verified["files"][2]["error"]["kind"], "truncated");
}

TEST(JsonContract, BatchReportMatchesItsSchema) {
  auto folder = schemas();
  const std::string dir = test::binary_dir() + "/json-contract-batch";
  std::filesystem::remove_all(dir);
  test::run_fapc("batch corpus/examples/fap corpus/fba-bad/truncated.fba -o '" + dir +
                 "/out' --to fap,fba --keep-going "
                 "--jobs 2 --report-json '" +
                 dir + "/report.json'");
  const nlohmann::json report = nlohmann::json::parse(test::read_text(dir + "/report.json"));
  EXPECT_EQ(joined(folder.validate(report, "batch-report.schema.json")), "");
  EXPECT_EQ(report["totals"]["jobs"], 6);
  EXPECT_EQ(report["totals"]["failed"], 1);
  EXPECT_EQ(report["totals"]["converted"], 5);
  std::set<std::string> codes;  // the failed job's error says what failed, by its code
  for (const nlohmann::json& job : report["jobs"])
    if (job["error"].is_object()) codes.insert(job["error"]["code"].get<std::string>());
  EXPECT_EQ(codes, std::set<std::string>{"fba.truncated"});
  std::filesystem::remove_all(dir);
}

// Every key a schema names is explained in docs/json.md (as `key`).
TEST(JsonContract, EverySchemaKeyIsDocumented) {
  const std::string doc = test::read_text(test::source_dir() + "/docs/json.md");
  for (const std::string& file : test::files_under(test::source_dir() + "/docs/json", ".schema.json")) {
    const std::string text = test::read_text(file);
    const std::regex property("\"([a-z_0-9]+)\": \\{");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), property); it != std::sregex_iterator(); ++it) {
      const std::string key = (*it)[1];
      if (key == "properties" || key == "items" || key == "error" || key == "format" || key == "totals" ||
          key == "additionalproperties")
        continue;
      EXPECT_NE(doc.find("`" + key + "`"), std::string::npos) << key << " (" << file << ") is not in docs/json.md";
    }
  }
}

TEST(JsonContract, TheValidatorRejectsWhatItMust) {
  auto folder = schemas();
  nlohmann::json good = {{"schema_version", 1},
                         {"error",
                          {{"severity", "error"},
                           {"kind", "io"},
                           {"code", "io.cannot_open"},
                           {"file", "x"},
                           {"line", nullptr},
                           {"column", nullptr},
                           {"byte", 4},
                           {"message", "m"},
                           {"text", "t"}}}};
  EXPECT_EQ(joined(folder.validate(good, "error.schema.json")), "");
  auto bad = good;
  bad["error"].erase("message");
  EXPECT_NE(joined(folder.validate(bad, "error.schema.json")).find("missing required key 'message'"),
            std::string::npos);
  bad = good;
  bad["extra"] = 1;
  EXPECT_NE(joined(folder.validate(bad, "error.schema.json")).find("'extra' is not in the schema"), std::string::npos);
  bad = good;
  bad["error"]["byte"] = "4";
  EXPECT_NE(joined(folder.validate(bad, "error.schema.json")).find("$.error.byte: expected"), std::string::npos);
  bad = good;
  bad["error"]["byte"] = -1;
  EXPECT_NE(joined(folder.validate(bad, "error.schema.json")).find("below"), std::string::npos);
  bad = good;
  bad["error"]["kind"] = "oops";
  EXPECT_NE(joined(folder.validate(bad, "error.schema.json")).find("is not one of"), std::string::npos);
  bad = good;
  bad["error"]["code"] = nullptr;  // an error always has a code; only a warning may lack one
  EXPECT_NE(joined(folder.validate(bad, "error.schema.json")).find("oneOf"), std::string::npos);
  bad["error"]["severity"] = "warning";
  EXPECT_EQ(joined(folder.validate(bad, "error.schema.json")), "");
  bad = good;
  bad["schema_version"] = 2;
  EXPECT_FALSE(folder.validate(bad, "error.schema.json").empty());
  const nlohmann::json verify = {
      {"schema_version", 1},
      {"files",
       {{{"file", "f"}, {"ok", true}, {"exit_status", 0}, {"error", 5}, {"warnings", nlohmann::json::array()}}}}};
  EXPECT_NE(joined(folder.validate(verify, "verify.schema.json")).find("oneOf"), std::string::npos);
}

}  // namespace
}  // namespace fapc
