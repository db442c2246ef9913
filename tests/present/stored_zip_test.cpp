// present/stored_zip.h: the CRC-32 against its published check value, the archive's bytes
// against the fields of PKWARE's APPNOTE.TXT, read back by Python's zipfile (an independent
// reader: names, bytes, CRCs; ZIP64 end records for more than 65535 files), and the refusals.
#include "present/stored_zip.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

namespace collide {
namespace {

std::uint64_t le(const std::string& s, std::size_t at, int bytes) {
    std::uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(s[at + i]);
    return v;
}

#ifdef COLLIDE_PYTHON3
// Python's exit status for `checks` (Python, after "import sys, zipfile" and z, the archive open
// with zipfile.ZipFile): 0 when every assert holds.
int python_reads(const std::string& zip, const std::string& checks) {
    const auto dir = std::filesystem::temp_directory_path() / ("collide-zip-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "a.zip", std::ios::binary) << zip;
    std::ofstream(dir / "read.py")
        << "import sys, zipfile\nz = zipfile.ZipFile(sys.argv[1])\nassert z.testzip() is None\n"
        << checks;
    const std::string cmd =
        std::string(COLLIDE_PYTHON3) + " " + (dir / "read.py").string() + " " + (dir / "a.zip").string();
    const int status = std::system(cmd.c_str());
    std::filesystem::remove_all(dir);
    return status;
}
#endif

TEST(StoredZip, Crc32CheckValues) {
    EXPECT_EQ(crc32("123456789"), 0xCBF43926u);  // the CRC-32 check value (ISO-HDLC)
    EXPECT_EQ(crc32(""), 0u);
    EXPECT_EQ(crc32("a"), 0xE8B7BE43u);  // RFC 1952's CRC of one byte, as zlib's crc32 gives it
}

TEST(StoredZip, FieldsAsAppnoteSaysThem) {
    const std::string zip = stored_zip({{"a.txt", "hello"}, {"d/b.xml", "<x/>"}});
    // Local header of a.txt at 0.
    EXPECT_EQ(le(zip, 0, 4), 0x04034b50u);
    EXPECT_EQ(le(zip, 8, 2), 0u);      // stored
    EXPECT_EQ(le(zip, 12, 2), 0x21u);  // 1980-01-01
    EXPECT_EQ(le(zip, 14, 4), crc32("hello"));
    EXPECT_EQ(le(zip, 18, 4), 5u);
    EXPECT_EQ(le(zip, 22, 4), 5u);
    EXPECT_EQ(le(zip, 26, 2), 5u);
    EXPECT_EQ(zip.substr(30, 10), "a.txthello");
    // Then d/b.xml's.
    EXPECT_EQ(le(zip, 40, 4), 0x04034b50u);
    EXPECT_EQ(zip.substr(70, 11), "d/b.xml<x/>");
    // The end record: 2 entries, the directory right after the files.
    const std::size_t end = zip.size() - 22;
    EXPECT_EQ(le(zip, end, 4), 0x06054b50u);
    EXPECT_EQ(le(zip, end + 10, 2), 2u);
    const std::size_t start = le(zip, end + 16, 4);
    EXPECT_EQ(start, 81u);
    EXPECT_EQ(le(zip, end + 12, 4), end - start);
    EXPECT_EQ(le(zip, start, 4), 0x02014b50u);
    EXPECT_EQ(le(zip, start + 16, 4), crc32("hello"));
    EXPECT_EQ(le(zip, start + 42, 4), 0u);  // a.txt's local header
    EXPECT_EQ(le(zip, start + 38, 4) >> 16, 0100644u);
    EXPECT_EQ(le(zip, start + 46 + 5 + 42, 4), 40u);  // d/b.xml's
    // The same files give the same bytes.
    EXPECT_EQ(zip, stored_zip({{"a.txt", "hello"}, {"d/b.xml", "<x/>"}}));
}

TEST(StoredZip, RefusesBadNames) {
    for (const std::string bad : {"", "/a", "a\\b", "../a", "a/../b", "a/..", "..", "caf\xc3\xa9"})
        EXPECT_THROW(stored_zip({{bad, "x"}}), std::invalid_argument) << bad;
    EXPECT_THROW(stored_zip({{"a", "x"}, {"a", "y"}}), std::invalid_argument);
    EXPECT_NO_THROW(stored_zip({{"a..b/c", "x"}}));
}

TEST(StoredZip, Zip64EndRecordsBeyond65535Files) {
    std::vector<ZipEntry> many;
    for (int i = 0; i < 65537; ++i) many.push_back({"f" + std::to_string(i), std::to_string(i)});
    const std::string zip = stored_zip(many);
    const std::size_t end = zip.size() - 22;
    EXPECT_EQ(le(zip, end + 10, 2), 0xFFFFu);
    EXPECT_EQ(le(zip, end - 20, 4), 0x07064b50u);  // the locator
    const std::size_t end64 = le(zip, end - 12, 8);
    EXPECT_EQ(le(zip, end64, 4), 0x06064b50u);
    EXPECT_EQ(le(zip, end64 + 32, 8), 65537u);
#ifdef COLLIDE_PYTHON3
    EXPECT_EQ(python_reads(zip,
                           "names = z.namelist()\n"
                           "assert len(names) == 65537, len(names)\n"
                           "assert all(z.read(n) == n[1:].encode() for n in ('f0', 'f65536', 'f40000'))\n"),
              0);
#endif
}

#ifdef COLLIDE_PYTHON3
TEST(StoredZip, PythonZipfileReadsItBack) {
    std::string binary;
    for (int i = 0; i < 256; ++i) binary += static_cast<char>(i);
    EXPECT_EQ(python_reads(stored_zip({{"imsmanifest.xml", "<manifest/>"}, {"figures/x.svg", binary}, {"empty", ""}}),
                           "assert z.namelist() == ['imsmanifest.xml', 'figures/x.svg', 'empty'], z.namelist()\n"
                           "assert z.read('figures/x.svg') == bytes(range(256))\n"
                           "assert z.read('empty') == b''\n"
                           "assert all(i.compress_type == zipfile.ZIP_STORED and i.date_time == (1980, 1, 1, 0, 0, 0)"
                           " and (i.external_attr >> 16) == 0o100644 for i in z.infolist())\n"),
              0);
}
#endif

}  // namespace
}  // namespace collide
