#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "atomic_file.h"
#include "errors.h"
#include "image_io.h"
#include "process.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

TEST(Ppm, DecodesP3WithCommentsAndMaxval) {
  const image_rgb8 img = decode_ppm("P3\n# a comment\n2 1\n# another\n15\n15 0 0  0 15 7\n", "t");
  ASSERT_EQ(img.width, 2);
  ASSERT_EQ(img.height, 1);
  EXPECT_EQ(img.rgb, (std::vector<std::uint8_t>{255, 0, 0, 0, 255, 119}));
}

TEST(Ppm, RejectsBrokenFiles) {
  EXPECT_THROW(decode_ppm("P6\n2 2\n255\nabc", "t"), image_read_error);        // truncated
  EXPECT_THROW(decode_ppm("P3\n2 1\n255\n1 2 3 4 5", "t"), image_read_error);  // truncated
  EXPECT_THROW(decode_ppm("P3\n1 1\n255\n1 2 300", "t"), image_read_error);    // above maxval
  EXPECT_THROW(decode_ppm("P3\n0 1\n255\n", "t"), image_read_error);           // zero width
  EXPECT_THROW(decode_ppm("P3\n1 1\n65535\n1 2 3", "t"), image_read_error);    // 16-bit
  EXPECT_THROW(decode_ppm("P3\nx 1\n255\n", "t"), image_read_error);
  // A forged header does not make the reader allocate gigabytes before noticing.
  EXPECT_THROW(decode_ppm("P6\n65536 65536\n255\n", "t"), image_read_error);
  try {
    decode_ppm("P6\n2 2\n255\nabc", "x.ppm");
    FAIL();
  } catch (const image_read_error& e) {
    EXPECT_NE(std::string(e.what()).find("x.ppm: truncated"), std::string::npos) << e.what();
  }
}

TEST(ReadImage, TellsFormatsApartByContent) {
  test::temp_dir dir;
  const auto fake = dir.path() / "fake.png";
  std::ofstream(fake) << "P3\n1 1\n255\n1 2 3\n";  // a PPM under a .png name still reads
  EXPECT_EQ(read_image(fake).rgb, (std::vector<std::uint8_t>{1, 2, 3}));
  const auto junk = dir.path() / "junk.png";
  std::ofstream(junk) << "this is not an image";
  EXPECT_THROW(read_image(junk), image_read_error);
  const auto bad_png = dir.path() / "bad.png";
  std::ofstream(bad_png) << "\x89PNG\r\n\x1a\n and then garbage";
  EXPECT_THROW(read_image(bad_png), image_read_error);
  EXPECT_THROW(read_image(dir.path() / "missing.ppm"), image_read_error);
}

TEST(OutputPath, ChecksExtensionAndFolder) {
  test::temp_dir dir;
  EXPECT_NO_THROW(check_output_path(dir.path() / "a.PNG", "-o"));
  EXPECT_THROW(check_output_path(dir.path() / "a.jpg", "-o"), usage_error);
  EXPECT_THROW(check_output_path(dir.path() / "a", "-o"), usage_error);
  EXPECT_THROW(check_output_path(dir.path() / "no" / "a.png", "-o"), usage_error);
  std::filesystem::create_directory(dir.path() / "d.png");
  EXPECT_THROW(check_output_path(dir.path() / "d.png", "-o"), usage_error);
}

// Writes, then replaces, a file, and checks what a reader sees: the content, a plain open()'s
// mode, and nothing else in the folder.
void expect_atomic_writes_replace_cleanly() {
  test::temp_dir dir;
  const std::filesystem::path path = dir.path() / "x.txt";
  write_file_atomically(path, "first");
  EXPECT_EQ(test::slurp(path), "first");
  write_file_atomically(path, "second, longer");  // replaces in place
  EXPECT_EQ(test::slurp(path), "second, longer");
  const mode_t mask = ::umask(0);
  ::umask(mask);
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask);
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1);
  EXPECT_THROW(write_file_atomically(dir.path() / "no" / "x.txt", "z"), std::runtime_error);
}

TEST(AtomicWrite, UnnamedTemporaryFileReplacesCleanly) {
  expect_atomic_writes_replace_cleanly();
}

TEST(AtomicWrite, NamedTemporaryFileFallbackReplacesCleanly) {
  struct fallback_forced {  // unset again even when an assertion ends the test early
    fallback_forced() { ::setenv("RTVK_TEST_NO_O_TMPFILE", "1", 1); }
    ~fallback_forced() { ::unsetenv("RTVK_TEST_NO_O_TMPFILE"); }
  } forced;
  expect_atomic_writes_replace_cleanly();
}

}  // namespace
}  // namespace rtvk
