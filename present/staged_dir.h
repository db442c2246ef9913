// An output directory written whole or not at all (`collide material`, `collide worksheet`):
// the files are built in a sibling directory DIR.tmp-PID and renamed into place at the end;
// a DIR that is not empty is refused unless forced (then replaced only once the new one is
// complete). Whatever stops the work before commit() leaves DIR as it was.
#pragma once

#include <filesystem>
#include <string>

namespace collide {

class StagedDirectory {
public:
    // Refuses `out_dir` when it exists and is not a directory, or is a directory that is not
    // empty without `force` (InputError naming it). Nothing is created yet.
    StagedDirectory(const std::string& out_dir, bool force);
    // Removes the staging directory when commit() did not run.
    ~StagedDirectory();
    StagedDirectory(const StagedDirectory&) = delete;
    StagedDirectory& operator=(const StagedDirectory&) = delete;

    // Creates the (empty) staging directory and returns it: write everything under it.
    const std::filesystem::path& begin();
    // Into place: an old DIR (forced) goes aside first, then away.
    void commit();

private:
    std::filesystem::path dir_, tmp_;
};

}  // namespace collide
