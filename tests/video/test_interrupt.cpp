// src/app/interrupt: signals become a flag, the flag becomes an Error.

#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <string>

#include "../support/temp_dir.hpp"
#include "collide/error.hpp"
#include "collide/io/file.hpp"
#include "interrupt.hpp"

using collide::app::InterruptGuard;
using collide::test::TempDir;

TEST_CASE("SIGINT sets the flag and throw_if_requested names the signal") {
    InterruptGuard guard;
    CHECK_FALSE(guard.requested());
    CHECK_NOTHROW(guard.throw_if_requested());
    std::raise(SIGINT);
    CHECK(guard.requested());
    CHECK(guard.flag().load());
    CHECK(guard.signal_number() == SIGINT);
    try {
        guard.throw_if_requested();
        FAIL("no error");
    } catch (const collide::Error& e) {
        CHECK(e.kind() == collide::ErrorKind::runtime);
        CHECK(std::string(e.what()).find("SIGINT") != std::string::npos);
    }
}

TEST_CASE("SIGTERM too, and a new guard starts clear") {
    InterruptGuard guard;
    CHECK_FALSE(guard.requested());
    std::raise(SIGTERM);
    CHECK(guard.signal_number() == SIGTERM);
}

TEST_CASE("only one guard at a time, the previous handler comes back afterwards") {
    struct sigaction before {};
    sigaction(SIGINT, nullptr, &before);
    {
        InterruptGuard guard;
        CHECK_THROWS_AS(InterruptGuard(), collide::Error);
    }
    struct sigaction after {};
    sigaction(SIGINT, nullptr, &after);
    const bool same_handler = after.sa_handler == before.sa_handler;
    CHECK(same_handler);
}

TEST_CASE("a second signal is harmless: the first one's clean stop goes on") {
    InterruptGuard guard;
    std::raise(SIGINT);
    std::raise(SIGINT);  // with SA_RESETHAND (before) this one killed the process mid-cleanup
    CHECK(guard.requested());
    CHECK(guard.signal_number() == SIGINT);
    struct sigaction now {};
    sigaction(SIGINT, nullptr, &now);
    const bool still_ours = now.sa_handler != SIG_DFL;
    CHECK(still_ours);
}

TEST_CASE("SIGHUP, SIGQUIT and SIGPIPE stop cleanly too, named in the one message") {
    for (const int signal_number : {SIGHUP, SIGQUIT, SIGPIPE}) {
        CAPTURE(signal_number);
        InterruptGuard guard;
        std::raise(signal_number);
        REQUIRE(guard.requested());
        const std::string name = signal_number == SIGHUP    ? "SIGHUP"
                                 : signal_number == SIGQUIT ? "SIGQUIT"
                                                            : "SIGPIPE";
        CHECK(guard.message() == "interrupted by " + name + "; nothing was written");
    }
}

TEST_CASE("a stop after the run put outputs in place never says that nothing was written") {
    TempDir dir("interrupt_after_commit");
    { const InterruptGuard clear; }  // the stop an earlier test's signal left set (no signal now)
    {
        // An earlier run's output (tests run many in one process) does not count.
        collide::io::OutputFile earlier(dir.path / "earlier.txt");
        earlier.write("x");
        earlier.commit();
    }
    {
        InterruptGuard guard;
        std::raise(SIGTERM);
        REQUIRE(guard.requested());
        CHECK(guard.message() == "interrupted by SIGTERM; nothing was written");
    }
    InterruptGuard guard;
    collide::io::OutputFile mine(dir.path / "mine.txt");
    mine.write("y");
    mine.commit();
    std::raise(SIGTERM);
    REQUIRE(guard.requested());
    CHECK(guard.message() == "interrupted by SIGTERM once the outputs were in place");
}

TEST_CASE("a third signal ends the process at once, for a clean stop that hangs") {
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        InterruptGuard guard;
        std::raise(SIGINT);
        std::raise(SIGINT);
        std::raise(SIGINT);  // the default action: the process ends here
        _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGINT);
}
