#include "present/stored_zip.h"

#include <array>
#include <set>
#include <stdexcept>

namespace collide {

namespace {

constexpr std::uint64_t kLimit = 0xFFFFFFFFull;           // 32-bit sizes and offsets: below this
constexpr std::uint16_t kDate = (0 << 9) | (1 << 5) | 1;  // 1980-01-01 in MS-DOS form (time 00:00 is 0)

void put16(std::string& o, std::uint64_t v) {
    for (int i = 0; i < 2; ++i) o += static_cast<char>((v >> (8 * i)) & 0xFF);
}
void put32(std::string& o, std::uint64_t v) {
    for (int i = 0; i < 4; ++i) o += static_cast<char>((v >> (8 * i)) & 0xFF);
}
void put64(std::string& o, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) o += static_cast<char>((v >> (8 * i)) & 0xFF);
}

void check_name(const std::string& name, std::set<std::string>& seen) {
    const auto bad = [&](const std::string& why) { throw std::invalid_argument("zip entry '" + name + "': " + why); };
    if (name.empty() || name.size() > 0xFFFF) bad("empty or too long");
    if (name.front() == '/') bad("absolute");
    for (const char c : name)
        if (c < 0x20 || c > 0x7E || c == '\\') bad("not printable ASCII with '/' between folders");
    if (name == ".." || name.rfind("../", 0) == 0 || name.find("/../") != std::string::npos ||
        (name.size() >= 3 && name.compare(name.size() - 3, 3, "/..") == 0))
        bad("a '..' step");
    if (!seen.insert(name).second) bad("given twice");
}

// The fields the local header and the central directory's entry share, from "version needed".
void common_fields(std::string& o, const ZipEntry& e, std::uint32_t crc) {
    put16(o, 10);  // version needed: 1.0, stored
    put16(o, 0);   // flags
    put16(o, 0);   // method: stored
    put16(o, 0);   // time 00:00:00
    put16(o, kDate);
    put32(o, crc);
    put32(o, e.data.size());  // compressed size: the same
    put32(o, e.data.size());
    put16(o, e.name.size());
    put16(o, 0);  // no extra field
}

}  // namespace

std::uint32_t crc32(const std::string& data) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFu;
    for (const char ch : data) c = table[(c ^ static_cast<unsigned char>(ch)) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

std::string stored_zip(const std::vector<ZipEntry>& entries) {
    std::set<std::string> seen;
    std::uint64_t total = 22 + 56 + 20;  // the end records
    for (const ZipEntry& e : entries) {
        check_name(e.name, seen);
        total += 30 + 46 + 2 * e.name.size() + e.data.size();
    }
    if (total >= kLimit)
        throw std::runtime_error("the zip archive would take " + std::to_string(total) +
                                 " bytes: 4 GiB or more needs ZIP64 sizes, which are not written");
    std::string out, directory;
    out.reserve(total);
    for (const ZipEntry& e : entries) {
        const std::uint32_t crc = crc32(e.data);
        const std::uint64_t offset = out.size();
        put32(out, 0x04034b50);
        common_fields(out, e, crc);
        out += e.name;
        out += e.data;
        put32(directory, 0x02014b50);
        put16(directory, (3 << 8) | 30);  // made by: Unix, 3.0 (the external attributes are a mode)
        common_fields(directory, e, crc);
        put16(directory, 0);                             // no comment
        put16(directory, 0);                             // disk 0
        put16(directory, 0);                             // internal attributes: binary
        put32(directory, std::uint64_t{0100644} << 16);  // a regular file, rw-r--r--
        put32(directory, offset);
        directory += e.name;
    }
    const std::uint64_t start = out.size(), count = entries.size();
    out += directory;
    if (count > 0xFFFF) {  // ZIP64: the counts do not fit the end record's 16 bits
        const std::uint64_t end64 = out.size();
        put32(out, 0x06064b50);
        put64(out, 44);  // the record's size after this field
        put16(out, 45);  // made by 4.5
        put16(out, 45);  // needed: 4.5, ZIP64
        put32(out, 0);   // this disk
        put32(out, 0);   // the directory's disk
        put64(out, count);
        put64(out, count);
        put64(out, directory.size());
        put64(out, start);
        put32(out, 0x07064b50);  // its locator
        put32(out, 0);
        put64(out, end64);
        put32(out, 1);  // disks
    }
    put32(out, 0x06054b50);
    put16(out, 0);
    put16(out, 0);
    put16(out, count > 0xFFFF ? 0xFFFF : count);
    put16(out, count > 0xFFFF ? 0xFFFF : count);
    put32(out, directory.size());
    put32(out, start);
    put16(out, 0);  // no comment
    return out;
}

}  // namespace collide
