// The rule for every file punchsweep writes (io::output_file_problem, issue 35 item 1): a
// new file or a regular file may be written; a link, a folder, a device, a pipe, a missing
// folder and an input (by inode: another spelling or a hard link) are refused, and a
// refused write leaves the file system as it was.
#include "io/output_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "scratch_dir.hpp"

namespace punchsweep::io {
namespace {

using testing::ScratchDir;

std::string read(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(OutputFile, a_new_file_and_a_regular_file_may_be_written) {
  const ScratchDir dir;
  EXPECT_EQ(output_file_problem(dir.file("new.ini")), "");
  write(dir.file("old.ini"), "old");
  EXPECT_EQ(output_file_problem(dir.file("old.ini"), {dir.file("other.csv")}), "");
  write_file_whole(dir.file("old.ini"), "new text\n");
  EXPECT_EQ(read(dir.file("old.ini")), "new text\n");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.file("")), {}), 1);  // no temporary left
}

TEST(OutputFile, links_folders_devices_and_pipes_are_refused_and_left_as_they_are) {
  const ScratchDir dir;
  write(dir.file("target"), "the link's target");
  std::filesystem::create_symlink(dir.file("target"), dir.file("link.ini"));
  std::filesystem::create_directory(dir.file("folder.ini"));
  ASSERT_EQ(::mkfifo(dir.file("pipe.ini").c_str(), 0600), 0);
  EXPECT_TRUE(contains(output_file_problem(dir.file("link.ini")), "link.ini is a symbolic link"));
  EXPECT_TRUE(contains(output_file_problem(dir.file("folder.ini")), "folder.ini is a folder"));
  EXPECT_TRUE(contains(output_file_problem(dir.file("pipe.ini")), "pipe.ini is a pipe"));
  EXPECT_TRUE(contains(output_file_problem("/dev/null"), "/dev/null is a character device"));  // only looked at
  for (const char* name : {"link.ini", "folder.ini", "pipe.ini"}) {
    EXPECT_THROW(write_file_whole(dir.file(name), "x"), std::runtime_error) << name;
  }
  EXPECT_TRUE(std::filesystem::is_symlink(dir.file("link.ini")));
  EXPECT_EQ(read(dir.file("target")), "the link's target");
  EXPECT_TRUE(std::filesystem::is_directory(dir.file("folder.ini")));
  EXPECT_EQ(std::filesystem::status(dir.file("pipe.ini")).type(), std::filesystem::file_type::fifo);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.file("")), {}), 4);  // no temporary left
}

TEST(OutputFile, an_input_is_refused_under_any_of_its_names) {
  const ScratchDir dir;
  write(dir.file("d.csv"), "measurements");
  std::filesystem::create_hard_link(dir.file("d.csv"), dir.file("hard.ini"));
  const std::string other_spelling = dir.file("") + "/./d.csv";
  EXPECT_TRUE(contains(output_file_problem(dir.file("d.csv"), {dir.file("d.csv")}), "is the input"));
  EXPECT_TRUE(contains(output_file_problem(other_spelling, {dir.file("d.csv")}), "is the input"));
  EXPECT_TRUE(contains(output_file_problem(dir.file("hard.ini"), {dir.file("d.csv")}), "is the input"));
  EXPECT_THROW(write_file_whole(dir.file("hard.ini"), "x", {dir.file("d.csv")}), std::runtime_error);
  EXPECT_EQ(read(dir.file("d.csv")), "measurements");
  EXPECT_EQ(output_file_problem(dir.file("new.ini"), {dir.file("d.csv"), dir.file("missing.csv")}), "");
}

TEST(OutputFile, a_missing_folder_is_named) {
  const ScratchDir dir;
  EXPECT_TRUE(contains(output_file_problem(dir.file("no/m.ini")), "the folder " + dir.file("no") + " does not exist"));
  write(dir.file("plain"), "");
  EXPECT_TRUE(contains(output_file_problem(dir.file("plain/m.ini")), "is not a folder"));
  EXPECT_TRUE(contains(output_file_problem(""), "empty"));
}

}  // namespace
}  // namespace punchsweep::io
