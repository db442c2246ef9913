#include "cli/exit_code.h"

#include <ostream>

#include "engine/run_error.h"
#include "scenario/input_error.h"

namespace collide::cli {

int run_command(std::ostream& err, const std::function<int()>& body,
                const std::function<std::string(const Interrupted&)>& interrupted_note) {
    try {
        return body();
    } catch (const Interrupted& e) {
        err << "collide: interrupted: " << (interrupted_note ? interrupted_note(e) : "stopped") << "\n";
        return kExitInterrupted;
    } catch (const InputError& e) {
        err << "collide: error: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const RunError& e) {
        err << "collide: error: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::runtime_error& e) {
        err << "collide: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        err << "collide: internal error: " << e.what() << "\n";
        return 1;
    }
}

int run_staged_command(std::ostream& err, const std::string& dir, const std::function<int()>& body) {
    return run_command(err, body, [&dir](const Interrupted&) { return dir + " is untouched"; });
}

}  // namespace collide::cli
