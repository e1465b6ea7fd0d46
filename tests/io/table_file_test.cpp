// Tables from CSV files (io/table_file.hpp): the rows read exactly, a header, comments, blank
// lines and CRLF skipped; each fault named by file and line.
#include "io/table_file.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "../support/scratch_path.hpp"
#include "core/error.hpp"

namespace flotsam {
namespace {

std::string message_of(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  try {
    read_table_file(path, "t", [](double v) { return v >= 0.0 ? "" : "a number >= 0"; });
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(TableFile, ReadsRowsAfterAHeaderSkippingCommentsBlanksAndCarriageReturns) {
  const auto dir = test::fresh_test_folder("flotsam_table_file_test");
  const std::string path = (dir / "q.csv").string();
  std::ofstream(path, std::ios::binary)
      << "t [s],Q [m^3/s]\r\n# gauged at the bridge\r\n0,10.5\r\n\r\n60 12.25  # blanks\r\n"
         "120,\t0\r\n";
  const auto rows = read_table_file(path, "t", [](double) { return std::string(); });
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], std::make_pair(0.0, 10.5));
  EXPECT_EQ(rows[1], std::make_pair(60.0, 12.25));
  EXPECT_EQ(rows[2], std::make_pair(120.0, 0.0));
  std::filesystem::remove_all(dir);
}

TEST(TableFile, FaultsAreNamedByFileAndLine) {
  const auto dir = test::fresh_test_folder("flotsam_table_file_faults");
  const std::string p = (dir / "q.csv").string();
  EXPECT_EQ(message_of(p, "0,1\n1,x\n"), p + ":2: expected two numbers 't, value', got '1,x'");
  EXPECT_EQ(message_of(p, "0,1\n1,2,3\n"), p + ":2: expected two numbers 't, value', got 3");
  EXPECT_EQ(message_of(p, "0,1\n0,2\n"),
            p + ":2: t = 0 does not come after the previous row's t = 0; a table's t must be "
                "strictly increasing");
  EXPECT_EQ(message_of(p, "t,Q\n0,1\n5,-2\n"), p + ":3: expected a number >= 0, got -2");
  EXPECT_EQ(message_of(p, "0,1\n1,inf\n"), p + ":2: expected two numbers 't, value', got '1,inf'");
  EXPECT_EQ(message_of(p, "t,Q\n# nothing\n"), p + ": the table has no rows");
  EXPECT_EQ(message_of(p, "t,Q\nt,Q\n"), p + ":2: expected two numbers 't, value', got 't,Q'");
  const std::string missing = (dir / "none.csv").string();
  try {
    read_table_file(missing, "t", [](double) { return std::string(); });
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot open the table file '" + missing + "': no such file");
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace flotsam
