#include "render/video.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace collide::render {

namespace fs = std::filesystem;

std::string find_program(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return "";
    std::stringstream dirs(path);
    for (std::string dir; std::getline(dirs, dir, ':');) {
        if (dir.empty()) continue;
        const std::string candidate = dir + "/" + program;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return "";
}

ProgramRun run_program(const std::vector<std::string>& args, const std::string& log,
                       const std::function<bool()>& stop) {
    std::vector<std::string> copy = args;
    std::vector<char*> argv;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    ProgramRun run;
    run.started = posix_spawn(&pid, copy.front().c_str(), &actions, nullptr, argv.data(), environ) == 0;
    posix_spawn_file_actions_destroy(&actions);
    if (!run.started) return run;
    int status = 0;
    // Waits for the child without losing it to a signal (EINTR: the command's handler ran).
    const auto reaped = [&](int options) {
        for (;;) {
            const pid_t r = ::waitpid(pid, &status, options);
            if (r == pid) return true;
            if (r == 0) return false;         // WNOHANG: still running
            if (errno != EINTR) return true;  // (no such child: nothing left to wait for)
        }
    };
    if (!stop) {
        reaped(0);
    } else {
        bool done = false;
        while (!(done = reaped(WNOHANG)) && !stop()) ::usleep(20000);
        if (!done) {
            ::kill(pid, SIGTERM);
            for (int k = 0; k < 100 && !(done = reaped(WNOHANG)); ++k) ::usleep(20000);
            if (!done) {
                ::kill(pid, SIGKILL);
                reaped(0);
            }
        }
        run.stopped = stop();
    }
    if (WIFEXITED(status)) run.exit = WEXITSTATUS(status);
    return run;
}

bool encode_video(const std::string& ffmpeg, const std::string& frames_dir, double fps, VideoFormat format,
                  const std::string& out_path, const std::function<bool()>& stop) {
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.6g", fps);
    const std::string tmp = out_path + ".tmp-" + std::to_string(::getpid());
    const std::string log =
        (fs::temp_directory_path() / ("collide-ffmpeg-" + std::to_string(::getpid()) + ".log")).string();
    std::vector<std::string> args = {
        ffmpeg, "-nostdin", "-y", "-loglevel", "error", "-framerate", rate, "-i", frames_dir + "/frame_%05d.png"};
    if (format == VideoFormat::mp4) {
        for (const char* a : {"-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
                              "-crf", "20", "-movflags", "+faststart", "-f", "mp4"})
            args.emplace_back(a);
    } else {
        char filter[256];
        std::snprintf(filter, sizeof filter,
                      "fps=%.6g,scale='min(640,iw)':-1:flags=lanczos,split[s0][s1];"
                      "[s0]palettegen=stats_mode=diff[p];[s1][p]paletteuse",
                      fps < 30 ? fps : 30.0);
        for (const char* a : {"-vf", static_cast<const char*>(filter), "-loop", "0", "-f", "gif"}) args.emplace_back(a);
    }
    args.push_back(tmp);

    const ProgramRun run = run_program(args, log, stop);
    std::string message;
    {
        std::ifstream in(log);
        std::stringstream text;
        text << in.rdbuf();
        message = text.str();
    }
    std::error_code ec;
    fs::remove(log, ec);
    if (run.stopped) {
        fs::remove(tmp, ec);
        return false;
    }
    if (!run.ok()) {
        fs::remove(tmp, ec);
        while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
        throw std::runtime_error(out_path + ": ffmpeg failed" +
                                 (!run.started      ? std::string(": cannot run ") + ffmpeg
                                  : message.empty() ? std::string()
                                                    : ": " + message));
    }
    fs::rename(tmp, out_path, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error(out_path + ": cannot write: " + ec.message());
    }
    return true;
}

}  // namespace collide::render
