// Ctrl-C for long commands (bake, compare): while a SigintScope lives, SIGINT only sets a flag
// (interrupted()) that the command's progress callback polls to cancel its work cleanly; the
// previous handler is restored when the scope ends. One scope at a time.
#pragma once

#include <atomic>
#include <csignal>

namespace pvs::app {

class SigintScope {
public:
    SigintScope();
    ~SigintScope();
    SigintScope(const SigintScope&) = delete;
    SigintScope& operator=(const SigintScope&) = delete;

    // The flag SIGINT sets (false when the scope began).
    static const std::atomic<bool>& interrupted();

private:
    struct sigaction previous_{};
};

} // namespace pvs::app
