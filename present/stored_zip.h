// A zip archive of stored (uncompressed) files, written whole in memory: the QTI package of
// `collide worksheet --format qti` (present/qti_package.h). PKWARE's APPNOTE.TXT: each file
// a local header and its bytes, then the central directory and its end record; the CRC-32 of
// each file (ISO 3309, the polynomial 0xEDB88320 reflected); every date 1980-01-01 00:00 (the
// format's first), so that the same files give the same bytes; Unix mode 0644. More than
// 65535 files take ZIP64's end records (the counts); an archive of 4 GiB or more is refused.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace collide {

struct ZipEntry {
    std::string name;  // "items/a.xml": '/' between folders, no leading '/', no "..", ASCII
    std::string data;
};

// The CRC-32 of zip and PNG (crc32("123456789") == 0xCBF43926, the check value).
std::uint32_t crc32(const std::string& data);

// The archive, its files in the order given. Throws std::invalid_argument for a name that is
// empty, absolute, holds "\" or a ".." step, a byte outside printable ASCII, or is given
// twice; std::runtime_error when the archive would reach 4 GiB.
std::string stored_zip(const std::vector<ZipEntry>& entries);

}  // namespace collide
