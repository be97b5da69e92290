#include "app/sigint_scope.h"

namespace pvs::app {

namespace {
// Set from the signal handler: a lock-free atomic store is async-signal-safe.
std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);
extern "C" void on_sigint(int) { g_interrupted.store(true); }
} // namespace

SigintScope::SigintScope()
{
    g_interrupted.store(false);
    struct sigaction action{};
    action.sa_handler = on_sigint;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_);
}

SigintScope::~SigintScope() { sigaction(SIGINT, &previous_, nullptr); }

const std::atomic<bool>& SigintScope::interrupted() { return g_interrupted; }

} // namespace pvs::app
