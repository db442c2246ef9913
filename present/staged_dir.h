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
    // empty without `force`, when it is the root or holds the current directory ("-o ."), when
    // it is a symbolic link that leads nowhere (a loop), and when its staging directory cannot
    // be created (InputError naming it): all before any work. "DIR/" is DIR; a symbolic link
    // to a directory is written through (its target is replaced). Creates the staging
    // directory.
    StagedDirectory(const std::string& out_dir, bool force);
    // Removes the staging directory when commit() did not run.
    ~StagedDirectory();
    StagedDirectory(const StagedDirectory&) = delete;
    StagedDirectory& operator=(const StagedDirectory&) = delete;

    // The (empty) staging directory: write everything under it.
    const std::filesystem::path& begin();
    // Into place: an old DIR (forced) goes aside first, then away.
    void commit();

private:
    std::string name_;  // as given, for messages
    std::filesystem::path dir_, tmp_;
};

}  // namespace collide
