#include "present/staged_dir.h"

#include <unistd.h>

#include "scenario/input_error.h"

namespace collide {

namespace fs = std::filesystem;

namespace {

// The directory `out_dir` names, as an absolute path without a trailing separator, checked
// before any work is done:
//   "DIR/" and "DIR" are the same directory (staged beside it as DIR.tmp-PID, not inside it);
//   a symbolic link is followed to its target (written there); one that leads nowhere (a loop,
//   a missing target) is refused;
//   the root, and a directory holding the current one ("-o .", "-o .."), cannot be replaced
//   (moved aside and deleted) and are refused.
fs::path output_path(const std::string& out_dir) {
    std::error_code ec;
    fs::path p(out_dir);
    if (fs::is_symlink(fs::symlink_status(p, ec))) {
        const fs::path real = fs::canonical(p, ec);
        if (ec)
            throw InputError(
                out_dir, {}, "",
                "is a symbolic link that leads nowhere (" + ec.message() + "); remove it or give another directory");
        p = real;
    }
    p = fs::absolute(p, ec);
    if (ec) throw InputError(out_dir, {}, "", "cannot be resolved: " + ec.message());
    p = p.lexically_normal();
    if (!p.has_filename()) p = p.parent_path();  // "DIR/", and "/here/." -> "/here/"
    if (p == p.root_path()) throw InputError(out_dir, {}, "", "is the root directory; give a directory to create");
    const fs::path here = fs::current_path(ec).lexically_normal();
    if (!ec) {
        const fs::path rel = here.lexically_relative(p);
        if (!rel.empty() && *rel.begin() != "..")
            throw InputError(out_dir, {}, "",
                             "holds the current directory, which cannot be replaced; give a new directory, "
                             "e.g. -o site");
    }
    return p;
}

}  // namespace

StagedDirectory::StagedDirectory(const std::string& out_dir, bool force) : name_(out_dir), dir_(output_path(out_dir)) {
    std::error_code ec;
    // A symbolic link inside the path that loops makes every test below fail with ELOOP: named.
    const fs::file_status st = fs::status(dir_, ec);
    if (ec && ec != std::errc::no_such_file_or_directory)
        throw InputError(out_dir, {}, "", "cannot be used: " + ec.message());
    if (fs::exists(st) && (!fs::is_directory(st) || (!fs::is_empty(dir_, ec) && !force)))
        throw InputError(out_dir, {}, "",
                         fs::is_directory(st) ? "directory is not empty (use --force to replace it)"
                                              : "exists and is not a directory");
    // The staging directory now, so that a place that cannot be written is refused before any
    // work (it is removed again unless commit() runs).
    tmp_ = dir_.parent_path() / (dir_.filename().string() + ".tmp-" + std::to_string(::getpid()));
    fs::remove_all(tmp_, ec);
    fs::create_directories(tmp_, ec);
    if (ec) {
        tmp_.clear();
        throw InputError(out_dir, {}, "", "cannot be written: " + ec.message());
    }
}

StagedDirectory::~StagedDirectory() {
    std::error_code ec;
    if (!tmp_.empty()) fs::remove_all(tmp_, ec);
}

const fs::path& StagedDirectory::begin() { return tmp_; }

void StagedDirectory::commit() {
    std::error_code ec;
    fs::path old;
    if (fs::exists(dir_, ec)) {
        old = dir_.parent_path() / (dir_.filename().string() + ".old-" + std::to_string(::getpid()));
        fs::rename(dir_, old, ec);
        if (ec) throw InputError(name_, {}, "", "cannot be replaced: " + ec.message());
    }
    fs::rename(tmp_, dir_, ec);
    if (ec) {
        if (!old.empty()) fs::rename(old, dir_);  // the old one back: DIR as it was
        throw InputError(name_, {}, "", "cannot be written: " + ec.message());
    }
    tmp_.clear();
    if (!old.empty()) fs::remove_all(old, ec);
}

}  // namespace collide
