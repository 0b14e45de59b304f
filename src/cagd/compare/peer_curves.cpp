#include "cagd/compare/peer_curves.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/io/child_process.hpp"

namespace cagd::compare {

namespace {

// The exit statuses of peers/run for a name that is no peer's, and for a peer not installed here.
constexpr int kNoSuchPeer = 2;
constexpr int kNotInstalled = 3;

}  // namespace

std::vector<PeerConfiguration> read_peer_manifest(const std::string& path) {
    const char* who = "cagd::compare::read_peer_manifest";
    const TextTable t =
        read_text_table(path, {"peer", "configuration", "closed", "library", "licence", "output", "call"});
    std::vector<PeerConfiguration> peers;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        PeerConfiguration c{.peer = t.at(r, "peer"),
                            .configuration = t.at(r, "configuration"),
                            .library = t.at(r, "library"),
                            .licence = t.at(r, "licence"),
                            .output = t.at(r, "output"),
                            .call = t.at(r, "call")};
        const std::string& closed = t.at(r, "closed");
        if (closed != "open" && closed != "closed" && closed != "both")
            fail_input(who, t.where(r) + ": closed \"" + excerpt(closed) + "\" is none of open, closed, both");
        c.open = closed != "closed", c.closed = closed != "open";
        if (c.output != "exact" && c.output != "samples")
            fail_input(who, t.where(r) + ": output \"" + excerpt(c.output) + "\" is neither exact nor samples");
        for (const std::string* name : {&c.peer, &c.configuration})
            if (name->empty() || name->find_first_of(" \t/") != std::string::npos || (*name)[0] == '.')
                fail_input(who,
                           t.where(r) + ": \"" + excerpt(*name) + "\" is not a name (no blanks, '/', leading '.')");
        for (const PeerConfiguration& other : peers)
            if (other.name() == c.name()) fail_input(who, t.where(r) + ": " + c.name() + " twice");
        peers.push_back(std::move(c));
    }
    if (peers.empty()) fail_input(who, t.source + ": no peer");
    return peers;
}

std::string peer_manifest_markdown(const std::vector<PeerConfiguration>& manifest) {
    std::string out =
        "| peer | configuration | curves | library | licence | output | how it is called |\n"
        "|---|---|---|---|---|---|---|\n";
    for (const PeerConfiguration& c : manifest)
        out += "| " + c.peer + " | `" + c.configuration + "` | " +
               (c.open && c.closed ? "open, closed"
                : c.open           ? "open"
                                   : "closed") +
               " | " + c.library + " | " + c.licence + " | " + c.output + " | " + c.call + " |\n";
    return out;
}

std::string peer_request_text(const std::vector<PeerRequest>& requests) {
    std::string text;
    char number[32];
    for (const PeerRequest& r : requests) {
        if (r.configuration.empty() || r.configuration.find_first_of(" \t\r\n") != std::string::npos)
            fail_input("cagd::compare::peer_request_text",
                       "configuration \"" + excerpt(r.configuration) + "\" is not a name (no blanks)");
        text += "curve " + r.configuration + (r.closed ? " closed " : " open ") + std::to_string(r.points.rows()) +
                " " + std::to_string(r.points.cols()) + "\n";
        for (Eigen::Index i = 0; i < r.points.rows(); ++i) {
            for (Eigen::Index k = 0; k < r.points.cols(); ++k) {
                std::snprintf(number, sizeof number, "%.17g", r.points(i, k));
                (text += k ? " " : "") += number;
            }
            text += "\n";
        }
    }
    return text;
}

PeerRun run_peer(const PeerLauncher& launcher, const std::string& peer, const std::vector<PeerRequest>& requests) {
    const std::vector<std::pair<std::string, std::string>> environment{{"CAGD_PEER_PROGRAMS", launcher.programs}};
    PeerRun run;
    const ProgramRun version = run_program({launcher.run, peer, "--version"}, "", environment, 60.0);
    if (version.started && version.exit_status == kNoSuchPeer)
        fail_input("cagd::compare::run_peer", last_line(version.error));
    if (!version.succeeded()) {
        run.reason = version.started && version.exit_status == kNotInstalled && !last_line(version.error).empty()
                         ? last_line(version.error)
                         : peer + ": peers/run " + peer + " --version: " + version.describe();
        return run;
    }
    run.installed = true;
    run.version = last_line(version.output);
    const ProgramRun answers = run_program({launcher.run, peer}, peer_request_text(requests), environment,
                                           60.0 + launcher.seconds_per_request * static_cast<double>(requests.size()));
    std::istringstream lines(answers.output);
    std::string line;
    for (std::size_t i = 0; i < requests.size() && std::getline(lines, line); ++i) {
        PeerAnswer a;
        const std::string source = peer + "'s answer " + std::to_string(i + 1);
        if (line.rfind("{\"error\"", 0) == 0) {
            const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
            a.error = j.is_object() && j.contains("error") && j["error"].is_string()
                          ? j["error"].get<std::string>()
                          : source + ": an error line that is not {\"error\": \"…\"}";
        } else {
            std::istringstream document(line);
            try {
                a.curve = exports::read_curve_json(document, source);
            } catch (const InvalidInput& e) {
                a.error = std::string("the peer's document is refused: ") + e.what();
            }
        }
        run.answers.push_back(std::move(a));
    }
    if (!answers.succeeded() || run.answers.size() != requests.size()) {
        run.reason = peer + ": " + std::to_string(run.answers.size()) + " answers to " +
                     std::to_string(requests.size()) + " requests; its adapter " + answers.describe();
        run.answers.assign(requests.size(), PeerAnswer{std::nullopt, run.reason});
    }
    return run;
}

}  // namespace cagd::compare
