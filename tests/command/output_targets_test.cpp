// What an output path may name (docs/security.md, "Outputs"), through every writer of the real
// program: a character device or a FIFO is written to, never replaced; a directory, a block
// device, a socket and a link to nothing are refused before any work; a link to a file replaces
// the file and keeps the link. Device nodes are made in a temporary folder of the build (mknod
// needs root: those tests are skipped otherwise), never in /dev. The null device's numbers
// (1, 3) are used so that what is written goes nowhere; a block device gets numbers no driver
// has, so that even a wrong open could write nothing.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "support/test_support.hpp"

namespace fapc {
namespace {

namespace fs = std::filesystem;

// Every writer of the program, each as "ARGS -o" to which the output path and its kind are added.
struct Writer {
  std::string name;
  std::string command;  // fapc ... -o (the output follows)
  std::string kind;     // --to KIND
};

std::vector<Writer> writers() {
  const std::string joy = test::corpus_dir() + "/examples/fap/joy.fap";
  const std::string mimic = test::corpus_dir() + "/examples/mimic/figure3.mimic";
  const std::string xmto = test::corpus_dir() + "/examples/xmto/compose.xmt";
  return {
      {"compile-fap", "compile " + joy + " -o", "fap"},  // streamed .fap to .fap
      {"compile-fba", "compile " + joy + " -o", "fba"},  // streamed .fap to .fba
      {"compile-mp4", "compile " + joy + " -o", "mp4"},
      {"compile-curves", "compile " + mimic + " -o", "json"},
      {"compile-script-fap", "compile " + mimic + " -o", "fap"},  // a script rendered frame by frame
      {"compile-script-fba", "compile " + mimic + " -o", "fba"},
      {"compile-xmto-fap", "compile " + xmto + " -o", "fap"},
      {"render-png", "render " + mimic + " --size 64x64 -o", "png"},
      {"render-webm", "render " + mimic + " --size 64x64 -o", "webm"},
      {"render-html", "render " + mimic + " --size 64x64 -o", "html"},
      {"plot-svg", "plot " + joy + " -o", "svg"},
      {"plot-png", "plot " + joy + " -o", "png"},
      {"plot-csv", "plot " + joy + " -o", "csv"},
      {"encode", "encode " + joy + " -o", ""},
      {"combine", "combine '" + joy + " + " + joy + "' -o", "fap"},
  };
}

class OutputTargets : public ::testing::Test {
 protected:
  fs::path dir;

  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = fs::path(test::binary_dir()) / "output-targets" / info->name();
    fs::remove_all(dir);
    fs::create_directories(dir);
  }

  std::string at(const std::string& name) const { return (dir / name).string(); }

  static std::string to(const Writer& w) { return w.kind.empty() ? "" : " --to " + w.kind; }

  void make_node(const std::string& name, mode_t type, unsigned major, unsigned minor) const {
    ASSERT_EQ(::mknod(at(name).c_str(), type | 0666, makedev(major, minor)), 0) << name;
  }

  // The node is still what it was: a device of these numbers, or a FIFO.
  void still_node(const std::string& name, mode_t type, unsigned major = 0, unsigned minor = 0) const {
    struct stat info {};
    ASSERT_EQ(::lstat(at(name).c_str(), &info), 0) << name << " is gone";
    EXPECT_EQ(info.st_mode & S_IFMT, type) << name << " changed type";
    if (type != S_IFIFO) {
      EXPECT_EQ(info.st_rdev, makedev(major, minor)) << name << " changed numbers";
    }
  }

  // No temporary file of an output left beside it.
  void nothing_left_beside() const {
    for (const auto& entry : fs::directory_iterator(dir))
      EXPECT_EQ(entry.path().filename().string().rfind(".fapc-tmp-", 0), std::string::npos) << entry.path();
  }
};

bool root() { return ::geteuid() == 0; }

// `fapc compile x.fap -o /dev/null` as root used to rename a regular file over the device node.
TEST_F(OutputTargets, EveryWriterWritesToACharacterDeviceAndKeepsIt) {
  if (!root()) GTEST_SKIP() << "mknod needs root";
  make_node("null", S_IFCHR, 1, 3);
  for (const Writer& w : writers()) {
    const test::CommandRun run = test::run_fapc(w.command + " " + at("null") + to(w));
    EXPECT_EQ(run.exit_status, 0) << w.name << "\n" << run.err;
    still_node("null", S_IFCHR, 1, 3);
  }
  nothing_left_beside();
}

TEST_F(OutputTargets, DecodeAndBatchReportsWriteToACharacterDevice) {
  if (!root()) GTEST_SKIP() << "mknod needs root";
  make_node("null", S_IFCHR, 1, 3);
  const std::string joy = test::corpus_dir() + "/examples/fap/joy.fap";
  ASSERT_EQ(test::run_fapc("encode " + joy + " -o " + at("joy.fba")).exit_status, 0);
  EXPECT_EQ(test::run_fapc("decode " + at("joy.fba") + " -o " + at("null") + " --to fap").exit_status, 0);
  still_node("null", S_IFCHR, 1, 3);
  fs::create_directories(dir / "in");
  fs::copy_file(joy, dir / "in" / "joy.fap");
  const test::CommandRun run = test::run_fapc("batch " + at("in") + " -o " + at("out") + " --report " + at("null") +
                                              " --report-json " + at("null"));
  EXPECT_EQ(run.exit_status, 0) << run.err;
  still_node("null", S_IFCHR, 1, 3);
}

// Through a FIFO the whole output arrives, as through standard output: the same bytes as a file.
TEST_F(OutputTargets, EveryWriterWritesItsWholeOutputThroughAFifo) {
  ASSERT_EQ(::mkfifo(at("pipe").c_str(), 0600), 0);
  for (const Writer& w : writers()) {
    // The reference has the FIFO's name (a .fap header names the output), in a folder of its own.
    fs::create_directories(dir / "reference");
    const std::string file = at("reference/pipe." + (w.kind.empty() ? std::string("fba") : w.kind));
    ASSERT_EQ(test::run_fapc(w.command + " " + file + to(w)).exit_status, 0) << w.name;
    // The reader is started first and waited for; the writer opens the FIFO when its output is whole.
    const test::CommandRun run =
        test::run_shell("cat " + at("pipe") + " > " + at("read") + " & reader=$!; " + test::fapc_program() + " " +
                        w.command + " " + at("pipe") + to(w) + "; status=$?; wait $reader; exit $status");
    EXPECT_EQ(run.exit_status, 0) << w.name << "\n" << run.err;
    still_node("pipe", S_IFIFO);
    // A video or page of the same animation is the same bytes; a plot may differ only in a name.
    const std::string expected = test::read_text(file), got = test::read_text(at("read"));
    if (w.kind == "fap" || w.kind == "fba" || w.kind == "csv" || w.kind == "json" || w.kind == "webm") {
      EXPECT_EQ(got, expected) << w.name;
    } else {
      EXPECT_EQ(got.size() > 0, expected.size() > 0) << w.name;
    }
  }
  nothing_left_beside();
}

// A FIFO gets nothing when the output fails: its reader sees an empty stream, not half an output.
TEST_F(OutputTargets, AFailedOutputWritesNothingToAFifo) {
  ASSERT_EQ(::mkfifo(at("pipe").c_str(), 0600), 0);
  std::ofstream(at("bad.fap")) << test::read_text(test::corpus_dir() + "/examples/fap/joy.fap") << "garbage\n";
  // The reader gives up after 3 s if nobody opens the FIFO (the expected outcome).
  const test::CommandRun run =
      test::run_shell("timeout 3 cat " + at("pipe") + " > " + at("read") + " & reader=$!; " + test::fapc_program() +
                      " compile " + at("bad.fap") + " -o " + at("pipe") +
                      " --to fap; status=$?; kill $reader 2>/dev/null; wait $reader; exit $status");
  EXPECT_EQ(run.exit_status, 1) << run.err;
  EXPECT_EQ(test::read_text(at("read")), "");
  still_node("pipe", S_IFIFO);
}

TEST_F(OutputTargets, ADirectoryIsRefusedBeforeTheWork) {
  fs::create_directories(dir / "folder");
  for (const Writer& w : writers()) {
    const test::CommandRun run = test::run_fapc(w.command + " " + at("folder") + to(w));
    EXPECT_EQ(run.exit_status, 1) << w.name;
    EXPECT_NE(run.err.find(at("folder") +
                           ": error: is a directory (an output is written to a file, a character device or a FIFO)"),
              std::string::npos)
        << w.name << "\n"
        << run.err;
    EXPECT_TRUE(fs::is_empty(dir / "folder")) << w.name;
  }
  nothing_left_beside();
}

TEST_F(OutputTargets, ABlockDeviceIsRefusedAndKept) {
  if (!root()) GTEST_SKIP() << "mknod needs root";
  make_node("disk", S_IFBLK, 240, 77);  // 240: a major number for local use, no driver behind it
  for (const Writer& w : writers()) {
    const test::CommandRun run = test::run_fapc(w.command + " " + at("disk") + to(w));
    EXPECT_EQ(run.exit_status, 1) << w.name;
    EXPECT_NE(run.err.find(at("disk") + ": error: is a block device"), std::string::npos) << w.name << "\n" << run.err;
    still_node("disk", S_IFBLK, 240, 77);
  }
}

TEST_F(OutputTargets, ASocketIsRefusedAndKept) {
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string path = at("socket");
  ASSERT_LT(path.size(), sizeof address.sun_path);
  path.copy(address.sun_path, path.size());
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  const test::CommandRun run =
      test::run_fapc("compile " + test::corpus_dir() + "/examples/fap/joy.fap -o " + path + " --to fap");
  ::close(fd);
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_NE(run.err.find(path + ": error: is a socket"), std::string::npos) << run.err;
  still_node("socket", S_IFSOCK);
}

TEST_F(OutputTargets, ALinkToAFileReplacesTheFileAndKeepsTheLink) {
  const std::string joy = test::corpus_dir() + "/examples/fap/joy.fap";
  fs::create_directories(dir / "elsewhere");
  std::ofstream(at("elsewhere/old.fap")) << "old\n";
  fs::permissions(at("elsewhere/old.fap"), fs::perms::owner_read | fs::perms::owner_write);
  fs::create_symlink("elsewhere/old.fap", dir / "link.fap");
  const test::CommandRun run = test::run_fapc("compile " + joy + " -o " + at("link.fap"));
  EXPECT_EQ(run.exit_status, 0) << run.err;
  ASSERT_EQ(test::run_fapc("compile " + joy + " -o " + at("old.fap")).exit_status, 0);  // what it should hold
  EXPECT_TRUE(fs::is_symlink(dir / "link.fap"));
  EXPECT_EQ(test::read_text(at("elsewhere/old.fap")), test::read_text(at("old.fap")));
  // The file replaced keeps its permissions: a private output stays private.
  EXPECT_EQ(fs::status(at("elsewhere/old.fap")).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write);
  for (const auto& entry : fs::directory_iterator(dir / "elsewhere")) EXPECT_EQ(entry.path().filename(), "old.fap");
}

TEST_F(OutputTargets, ALinkToNothingIsRefused) {
  fs::create_symlink("missing/x.fap", dir / "dangling.fap");
  const test::CommandRun run =
      test::run_fapc("compile " + test::corpus_dir() + "/examples/fap/joy.fap -o " + at("dangling.fap"));
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_NE(run.err.find("dangling.fap: error: is a symbolic link to 'missing/x.fap', which does not exist"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir / "missing"));
  EXPECT_TRUE(fs::is_symlink(dir / "dangling.fap"));
}

}  // namespace
}  // namespace fapc
