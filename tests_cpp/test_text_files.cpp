// Text and files without iostreams (text.hpp, c_file.hpp): numbers come out as an ostream
// writes them, whatever the C locale; numbers are read whole; files and folders behave as
// std::fstream and std::filesystem did.
#include <gtest/gtest.h>

#include <cerrno>
#include <clocale>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

#include "util/c_file.hpp"
#include "util/text.hpp"

using namespace contactbody;

namespace {

const double values[] = {0.0,
                         -0.0,
                         1.0,
                         -2.5,
                         0.1,
                         1.0 / 3,
                         123456.0,
                         1234567.0,
                         1e-5,
                         2.5e-7,
                         6.02214076e23,
                         -1.6e-19,
                         1e300,
                         4.9e-324,
                         std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::quiet_NaN()};

std::string ostream_text(double x, int precision) {
    std::ostringstream s;
    s.precision(precision);
    s << x;
    return s.str();
}

TEST(Text, NumbersAsAnOstreamWritesThem) {
    for (int precision : {6, 17})
        for (double x : values) EXPECT_EQ(format_number(x, precision), ostream_text(x, precision));
}

TEST(Text, DecimalPointWhateverTheCLocale) {
    const char* names[] = {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "de_DE", "German_Germany"};
    const char* set = nullptr;
    for (const char* name : names)
        if ((set = std::setlocale(LC_NUMERIC, name))) break;
    if (!set) GTEST_SKIP() << "no locale with a decimal comma installed";
    char printed[32];
    std::snprintf(printed, sizeof printed, "%g", 2.5);
    const std::string text = format_number(2.5);
    std::setlocale(LC_NUMERIC, "C");
    ASSERT_STREQ(printed, "2,5") << "the locale " << set << " should print a decimal comma";
    EXPECT_EQ(text, "2.5");
}

TEST(Text, MessagesAsAnOstringstreamBuildsThem) {
    Text t;
    std::ostringstream o;
    const long index = -42;
    const size_t count = 7;
    t << "F = " << 0.3 << ", " << index << " of " << count << ' ' << true << std::string(" J/m ") << 1e-9f;
    o << "F = " << 0.3 << ", " << index << " of " << count << ' ' << true << std::string(" J/m ") << 1e-9f;
    EXPECT_EQ(t.str(), o.str());
    t.precision(17);
    o.precision(17);
    t << 0.1;
    o << 0.1;
    EXPECT_EQ(t.str(), o.str());
}

TEST(Text, ReadsWholeFiniteNumbers) {
    const std::pair<const char*, double> good[] = {{"1.5", 1.5}, {"  -3e-2\t", -0.03}, {"+2", 2}, {".5", 0.5},
                                                   {"7.", 7},    {"1E3", 1000}};
    for (const auto& [text, value] : good) {
        double x = 0;
        EXPECT_TRUE(parse_number(text, x)) << text;
        EXPECT_EQ(x, value) << text;
    }
    for (const char* text :
         {"", "  ", "1.5x", "1,5", "inf", "nan", "-inf", "1e999", "+-1", "++1", "--1", "0x10", "1 2", "e5"}) {
        double x = 0;
        EXPECT_FALSE(parse_number(text, x)) << '\'' << text << '\'';
    }
}

class Files : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = join_path(
            ::testing::TempDir(),
            std::string("c_file_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    std::string dir_;
};

std::string read_all(const std::string& path) {
    File f = open_file(path, "rb");
    if (!f) return "<missing>";
    std::string s;
    char b[256];
    for (size_t n; (n = std::fread(b, 1, sizeof b, f.get())) > 0;) s.append(b, n);
    return s;
}

TEST_F(Files, FoldersAreMadeListedAndFilesReplaced) {
    const std::string nested = join_path(join_path(dir_, "a"), "b/");
    ASSERT_TRUE(create_directories(nested));
    EXPECT_TRUE(create_directories(nested));  // already there
    const std::string target = join_path(nested, "x.txt"), tmp = target + ".tmp";
    EXPECT_EQ(join_path("", "x"), "x");
    EXPECT_EQ(join_path("d/", "x"), "d/x");
    for (const char* text : {"first", "second"}) {
        File f = open_file(tmp, "wb");
        ASSERT_TRUE(f);
        std::fputs(text, f.get());
        f.reset();
        ASSERT_TRUE(replace_file(tmp, target)) << std::strerror(errno);  // replaces the first
        EXPECT_EQ(read_all(target), text);
    }
    std::vector<std::string> names = directory_entries(nested);
    EXPECT_EQ(names, std::vector<std::string>{"x.txt"});
    EXPECT_TRUE(remove_file(target));
    EXPECT_TRUE(directory_entries(nested).empty());
    EXPECT_FALSE(remove_file(target));
    EXPECT_TRUE(directory_entries(join_path(dir_, "missing")).empty());
    // A file where a folder should be: an error, not a crash.
    File blocker = open_file(join_path(dir_, "file"), "wb");
    blocker.reset();
    EXPECT_FALSE(create_directories(join_path(join_path(dir_, "file"), "sub")));
    EXPECT_FALSE(open_file(join_path(join_path(dir_, "missing"), "x"), "rb"));
}

TEST_F(Files, OffsetsBeyondFourGigabytes) {
    ASSERT_TRUE(create_directories(dir_));
    const std::string path = join_path(dir_, "big.bin");
    File f = open_file(path, "w+b");
    ASSERT_TRUE(f);
    const uint64_t far = (uint64_t{1} << 32) + 5;  // a 32-bit offset would wrap to 5
    ASSERT_TRUE(resize_file(f.get(), far + 1));    // sparse where the file system allows
    ASSERT_TRUE(seek_file(f.get(), far));
    ASSERT_EQ(std::fputc('z', f.get()), 'z');
    ASSERT_TRUE(seek_file(f.get(), 5));
    ASSERT_EQ(std::fputc('a', f.get()), 'a');
    ASSERT_TRUE(seek_file(f.get(), far));
    EXPECT_EQ(std::fgetc(f.get()), 'z');
    ASSERT_TRUE(seek_file(f.get(), 5));
    EXPECT_EQ(std::fgetc(f.get()), 'a');
    ASSERT_TRUE(resize_file(f.get(), 3));
    ASSERT_TRUE(seek_file(f.get(), 0));
    char b[8];
    EXPECT_EQ(std::fread(b, 1, sizeof b, f.get()), 3u);  // cut to 3 bytes
    f.reset();
    EXPECT_TRUE(remove_file(path));
}

}  // namespace
