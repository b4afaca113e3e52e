// src/app/interrupt: signals become a flag, the flag becomes an Error.

#include <doctest/doctest.h>

#include <csignal>

#include "collide/error.hpp"
#include "interrupt.hpp"

using collide::app::InterruptGuard;

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

TEST_CASE("each handler fires once: a second signal would get the default action") {
    InterruptGuard guard;
    std::raise(SIGINT);
    CHECK(guard.requested());
    struct sigaction now {};
    sigaction(SIGINT, nullptr, &now);
    const bool default_action = now.sa_handler == SIG_DFL;
    CHECK(default_action);
}
