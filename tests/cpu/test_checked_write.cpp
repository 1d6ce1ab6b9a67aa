// writeFileChecked and AppendFile (renderer/checked_write.h): a write either lands whole under its name or
// fails with the file and the reason, leaving nothing behind; a device or FIFO is written in place, never
// replaced by a renamed file.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>
#include <vector>

#include <cstdlib>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "renderer/checked_write.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

// A fresh folder for one test, removed after it.
class TempFolder {
 public:
  TempFolder() {
    std::string pattern = (fs::temp_directory_path() / "raylab-checked-write-XXXXXX").string();
    path_ = ::mkdtemp(pattern.data()) ? pattern : "";
  }
  ~TempFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const std::string& path() const { return path_; }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }
  std::vector<std::string> names() const {  // hidden temporary files included
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(path_)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  std::string path_;
};

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The message of the WriteError `write` throws, or "" when it throws none.
template <typename F>
std::string failureOf(F write) {
  try {
    write();
  } catch (const WriteError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckedWrite, SuccessLeavesExactlyTheFile) {
  TempFolder dir;
  ASSERT_FALSE(dir.path().empty());
  writeFileChecked(dir / "a.json", "first, longer text\n");
  writeFileChecked(dir / "a.json", "second\n");  // replaces, never appends or leaves the old tail
  EXPECT_EQ(contents(dir / "a.json"), "second\n");
  EXPECT_EQ(dir.names(), std::vector<std::string>{"a.json"});
  struct stat st {};
  ASSERT_EQ(::stat((dir / "a.json").c_str(), &st), 0);
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask) << "a new file gets the mode open(0666) would give, not mkstemp's 0600";
}

TEST(CheckedWrite, MissingFolderReportsAndLeavesNothing) {
  TempFolder dir;
  const std::string path = dir / "missing/a.json";
  const std::string failure = failureOf([&] { writeFileChecked(path, "x"); });
  EXPECT_NE(failure.find(path), std::string::npos) << failure;
  EXPECT_NE(failure.find("No such file or directory"), std::string::npos) << failure;
  EXPECT_TRUE(dir.names().empty());
}

TEST(CheckedWrite, ProcReportsAndLeavesNothing) {
  const std::string path = "/proc/raylab-checked-write-test.json";
  const std::string failure = failureOf([&] { writeFileChecked(path, "{}"); });
  EXPECT_NE(failure.find(path), std::string::npos) << failure;
  EXPECT_NE(failure.find("temporary file"), std::string::npos) << failure;
  EXPECT_FALSE(fs::exists(path));
}

TEST(CheckedWrite, DevFullReportsNoSpaceAndStaysADevice) {
  struct stat st {};
  if (::stat("/dev/full", &st) != 0 || !S_ISCHR(st.st_mode)) GTEST_SKIP() << "no /dev/full here";
  const std::string failure = failureOf([] { writeFileChecked("/dev/full", "lost bytes"); });
  EXPECT_NE(failure.find("/dev/full"), std::string::npos) << failure;
  EXPECT_NE(failure.find("No space left on device"), std::string::npos) << failure;
  ASSERT_EQ(::stat("/dev/full", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/full was replaced";
  for (const auto& e : fs::directory_iterator("/dev"))
    EXPECT_NE(e.path().filename().string().rfind(".full.", 0), 0u) << "a temporary file was left: " << e.path();
}

TEST(CheckedWrite, FifoIsWrittenInPlace) {
  TempFolder dir;
  const std::string fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto reader = std::async(std::launch::async, [&] { return contents(fifo); });  // opening blocks until a writer
  writeFileChecked(fifo, "through the pipe");
  EXPECT_EQ(reader.get(), "through the pipe");
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced by a file";
  EXPECT_EQ(dir.names(), std::vector<std::string>{"pipe"});
}

TEST(CheckedWrite, LinkKeepsPointingAtTheReplacedFile) {
  TempFolder dir;
  writeFileChecked(dir / "real.txt", "old");
  fs::create_symlink(dir / "real.txt", dir / "link.txt");
  writeFileChecked(dir / "link.txt", "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(contents(dir / "real.txt"), "new");
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"link.txt", "real.txt"}));
}

TEST(CheckedWrite, AppendsWholeRecordsAndReportsFailures) {
  TempFolder dir;
  {
    AppendFile log(dir / "log.jsonl", AppendFile::Start::Empty);
    log.append("{\"a\":1}\n", /*durable=*/true);
    log.append("{\"b\":2}\n", /*durable=*/false);
    log.close();
  }
  AppendFile more(dir / "log.jsonl", AppendFile::Start::Keep);
  more.append("{\"c\":3}\n", true);
  more.close();
  EXPECT_EQ(contents(dir / "log.jsonl"), "{\"a\":1}\n{\"b\":2}\n{\"c\":3}\n");

  EXPECT_NE(failureOf([&] { AppendFile(dir / "missing/log.jsonl", AppendFile::Start::Empty); }).find("missing/log.jsonl"),
            std::string::npos);
  struct stat st {};
  if (::stat("/dev/full", &st) != 0) return;
  AppendFile full("/dev/full", AppendFile::Start::Keep);
  const std::string failure = failureOf([&] { full.append("a record\n", true); });
  EXPECT_NE(failure.find("No space left on device"), std::string::npos) << failure;
}

}  // namespace
}  // namespace raylab
