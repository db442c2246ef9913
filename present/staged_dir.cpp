#include "present/staged_dir.h"

#include <unistd.h>

#include "scenario/input_error.h"

namespace collide {

namespace fs = std::filesystem;

StagedDirectory::StagedDirectory(const std::string& out_dir, bool force) : dir_(out_dir) {
    std::error_code ec;
    if (fs::exists(dir_, ec) && (!fs::is_directory(dir_, ec) || (!fs::is_empty(dir_, ec) && !force)))
        throw InputError(out_dir, {}, "",
                         fs::is_directory(dir_, ec) ? "directory is not empty (use --force to replace it)"
                                                    : "exists and is not a directory");
}

StagedDirectory::~StagedDirectory() {
    std::error_code ec;
    if (!tmp_.empty()) fs::remove_all(tmp_, ec);
}

const fs::path& StagedDirectory::begin() {
    std::error_code ec;
    tmp_ = dir_.parent_path() / (dir_.filename().string() + ".tmp-" + std::to_string(::getpid()));
    fs::remove_all(tmp_, ec);
    fs::create_directories(tmp_);
    return tmp_;
}

void StagedDirectory::commit() {
    std::error_code ec;
    fs::path old;
    if (fs::exists(dir_, ec)) {
        old = dir_.parent_path() / (dir_.filename().string() + ".old-" + std::to_string(::getpid()));
        fs::rename(dir_, old);
    }
    fs::rename(tmp_, dir_);
    tmp_.clear();
    if (!old.empty()) fs::remove_all(old, ec);
}

}  // namespace collide
