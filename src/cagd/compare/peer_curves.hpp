#pragma once
/// @file
/// The benchmark's peers: other libraries' interpolants (peers/peers.csv lists them), each run as
/// its users run it by an adapter of its own under peers/PEER/, launched by peers/run, never
/// linked (several are GPL or AGPL, some JavaScript).
///
/// The protocol (docs/peers.md). `peers/run PEER --version` prints the peer's name and version, or
/// exits 3 with the reason on standard error when the peer is not installed. `peers/run PEER` reads
/// requests on standard input, each a line `curve CONFIGURATION open|closed N D` and N lines of D
/// coordinates (at 17 significant digits), and answers each with one line on standard output: a
/// curve document of the peer's own exact pieces (export/curve_json.hpp; read with its limits and
/// checks), or {"error": "…"} when the peer refuses the points or fails on them.
///
/// The manifest peers/peers.csv lists every peer's configurations (one row each): peer,
/// configuration, closed (open, closed or both), library, licence, output (exact or samples), call
/// (how the adapter calls the library, as its users do).
#include <optional>
#include <string>
#include <vector>

#include "cagd/core/points.hpp"
#include "cagd/export/curve_json.hpp"

namespace cagd::compare {

/// One configuration of a peer (a row of peers/peers.csv; see above).
struct PeerConfiguration {
    std::string peer{};           ///< the adapter's folder under peers/
    std::string configuration{};  ///< its name in requests
    bool open = false;            ///< draws open curves
    bool closed = false;          ///< draws closed curves
    std::string library{};        ///< the library and where it comes from
    std::string licence{};        ///< the library's licence
    std::string output{};         ///< "exact" or "samples"
    std::string call{};           ///< how the adapter calls it
    /// "peer:configuration", the name in tables.
    std::string name() const { return peer + ":" + configuration; }
};
/// The manifest at `path` (see above); InvalidInput naming path:line for a bad row.
std::vector<PeerConfiguration> read_peer_manifest(const std::string& path);
/// The manifest as a Markdown table, one row per configuration (docs/methods.md's peers).
std::string peer_manifest_markdown(const std::vector<PeerConfiguration>& manifest);

/// Where the peers are: the launcher peers/run and the folder of the built adapter programs.
struct PeerLauncher {
    std::string run;                    ///< the path of peers/run
    std::string programs;               ///< CAGD_PEER_PROGRAMS: where cmake built cagd-peer-PEER
    double seconds_per_request = 30.0;  ///< a peer's run may take this long per request
};

/// One request (see above).
struct PeerRequest {
    std::string configuration;  ///< the peer's configuration
    PointList points;           ///< the points (2 or 3 columns)
    bool closed = false;        ///< a closed curve
};
/// The answer to one request: the peer's curve, or why there is none.
struct PeerAnswer {
    std::optional<exports::CurveDocument> curve;  ///< the peer's pieces
    std::string error;                            ///< the peer's refusal or failure (empty with a curve)
};
/// A peer's run over many requests.
struct PeerRun {
    bool installed = false;           ///< false: skipped (`reason` says why)
    std::string version;              ///< the adapter's --version line
    std::string reason;               ///< why it was skipped, or why the whole run failed
    std::vector<PeerAnswer> answers;  ///< one per request (all with `reason` as error when the run failed)
};

/// The request lines of `requests` (see above); InvalidInput for a configuration that is empty or
/// holds blanks (it would break its line).
std::string peer_request_text(const std::vector<PeerRequest>& requests);
/// Runs `peer` on `requests` in one process of its adapter (see above). InvalidInput when the
/// launcher knows no such peer (its exit status 2); a peer that is not installed is skipped; a run that ends badly (a
/// crash, a time-out, fewer answers than requests) answers every request with that failure, named as the peer's.
PeerRun run_peer(const PeerLauncher& launcher, const std::string& peer, const std::vector<PeerRequest>& requests);

}  // namespace cagd::compare
