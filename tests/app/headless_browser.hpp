#pragma once
// Headless Chromium for the tests of pages collide writes (the slide player, a <track> page):
// the page's `?test` script logs what it saw into <pre id="test-log"> and ends the log with "end".
#include <cstdlib>
#include <filesystem>
#include <string>

#include "../support/shell.hpp"

namespace collide::test {

/// The Chromium on PATH ("chromium", "chromium-browser", "google-chrome"), or "" when none is.
inline std::string chromium_program() {
    for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
        if (std::system(("command -v " + std::string(name) + " >/dev/null 2>&1").c_str()) == 0)
            return name;
    }
    return "";
}

/// The page's DOM after `budget_ms` of virtual time in headless Chromium, with its own profile
/// folder (nothing of the user's is touched).
inline std::string page_dom(const std::string& chromium, const std::filesystem::path& profile,
                            const std::string& url, int budget_ms) {
    return capture("timeout 120 " + chromium +
                   " --headless --no-sandbox --disable-gpu --no-first-run --mute-audio"
                   " --autoplay-policy=no-user-gesture-required --virtual-time-budget=" +
                   std::to_string(budget_ms) + " --user-data-dir=" + profile.string() +
                   " --dump-dom '" + url + "' 2>/dev/null");
}

/// The text of <pre id="test-log"> in `dom` ("" when the page has none).
inline std::string test_log(const std::string& dom) {
    const std::size_t open = dom.find("<pre id=\"test-log\"");
    if (open == std::string::npos) return "";
    const std::size_t from = dom.find('>', open) + 1;
    return dom.substr(from, dom.find("</pre>", from) - from);
}

/// The page's test log once its script has ended ("end" in the log). The video in the page loads
/// and plays in real time, not in Chromium's virtual time: on a loaded machine the budget can run
/// out before the script ends, so the page is opened again with three and then nine times the
/// budget. The log of the last try is returned whatever it holds: the caller's checks judge it.
inline std::string finished_test_log(const std::string& chromium,
                                     const std::filesystem::path& profile, const std::string& url,
                                     int budget_ms) {
    std::string log;
    for (const int factor : {1, 3, 9}) {
        log = test_log(page_dom(chromium, profile, url, budget_ms * factor));
        if (log.find("end") != std::string::npos) break;
    }
    return log;
}

}  // namespace collide::test
