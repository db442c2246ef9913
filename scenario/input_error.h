// Errors in user input: they name the file, the line and column where known, and the key.
// The command prints one such message on stderr and exits with code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace collide {

// A message is one line on stderr, but the user text it quotes (a name, a key, a value) may hold
// a line break ("""cart\n"""), a tab or another control character: those are shown as the
// escape a TOML string would use (\n, \t, \r, \u007F), so 'cart\n' shows what to change.
inline std::string one_line(const std::string& text) {
    std::string s;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') s += "\\n";
        else if (c == '\t') s += "\\t";
        else if (c == '\r') s += "\\r";
        else if (u < 0x20 || u == 0x7f) {
            const char* hex = "0123456789ABCDEF";
            s += "\\u00";
            s += hex[u >> 4];
            s += hex[u & 15];
        } else {
            s += c;
        }
    }
    return s;
}

struct SourcePos {
    int line = 0;    // 1-based; 0 = unknown
    int column = 0;  // 1-based; 0 = unknown
};

class InputError : public std::runtime_error {
public:
    InputError(std::string file, SourcePos pos, std::string key, std::string message)
        : std::runtime_error(format(file, pos, key, message)),
          file_(std::move(file)),
          pos_(pos),
          key_(std::move(key)),
          message_(std::move(message)) {}

    const std::string& file() const { return file_; }
    SourcePos pos() const { return pos_; }
    const std::string& key() const { return key_; }
    const std::string& message() const { return message_; }

    // "FILE:LINE:COL: key: message" (parts that are unknown are left out), on one line.
    // Without a file, "LINE:COL: key: message" (text that came from no file: the WebAssembly
    // module's, wasm/).
    static std::string format(const std::string& file, SourcePos pos, const std::string& key,
                              const std::string& message) {
        std::string s = file;
        if (pos.line > 0) s += (s.empty() ? "" : ":") + std::to_string(pos.line);
        if (pos.line > 0 && pos.column > 0) s += ":" + std::to_string(pos.column);
        if (!s.empty()) s += ": ";  // no file: a command-line option, named by its key
        if (!key.empty()) s += key + ": ";
        return one_line(s + message);
    }

private:
    std::string file_;
    SourcePos pos_;
    std::string key_;
    std::string message_;
};

}  // namespace collide
