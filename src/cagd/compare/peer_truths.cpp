#include "cagd/compare/peer_truths.hpp"

#include <string>

#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"

namespace cagd::compare {

std::vector<TruthRun> subject_truth_runs(const std::vector<CurveSubject>& subjects, const std::vector<int>& sizes,
                                         int threads) {
    check_truth_sizes(sizes, "cagd::compare::subject_truth_runs");
    if (threads <= 0) threads = hardware_threads();
    struct Case {
        const TruthFamily* family;
        bool closed;
        int n;
        TruthSample sample;
    };
    std::vector<Case> cases;
    for (const TruthFamily& f : truth_families())
        for (bool closed : {true, false})
            if (!closed || f.closed)
                for (int n : sizes) cases.push_back({&f, closed, n, {}});
    parallel_for(static_cast<long>(cases.size()), threads, [&](long k) {
        Case& c = cases[static_cast<std::size_t>(k)];
        c.sample = truth_samples(*c.family, c.n, TruthSpacing::uniform, c.closed);
    });
    std::vector<CurveRequest> requests;
    for (const Case& c : cases) requests.push_back({c.sample.points, c.closed});
    std::vector<TruthRun> runs;
    for (const CurveSubject& subject : subjects) {
        const std::vector<DrawnCurve> drawn = subject.draw(requests);
        // The extensions (extensionality()) of the curves drawn, in a second batch.
        std::vector<ExtendedPoints> extended(cases.size());
        std::vector<CurveRequest> more;
        std::vector<long> more_of(cases.size(), -1);
        for (std::size_t k = 0; k < cases.size(); ++k) {
            if (!drawn[k].interpolant) continue;
            extended[k] = extended_points(cases[k].sample.points, cases[k].closed, *drawn[k].interpolant);
            more_of[k] = static_cast<long>(more.size());
            more.push_back({extended[k].points, cases[k].closed});
        }
        const std::vector<DrawnCurve> again = more.empty() ? std::vector<DrawnCurve>{} : subject.draw(more);
        std::vector<TruthRun> mine(cases.size());
        parallel_for(static_cast<long>(cases.size()), threads, [&](long index) {
            const auto k = static_cast<std::size_t>(index);
            const Case& c = cases[k];
            TruthRun& r = mine[k];
            r.family = c.family->name, r.spacing = TruthSpacing::uniform, r.closed = c.closed, r.n = c.n;
            r.method = subject.name;
            r.truth_shape = shape_measures(*c.family->curve, c.sample.params, c.closed);
            r.status = drawn[k].status;
            r.note = drawn[k].note;
            if (!drawn[k].interpolant) return;
            const methods::Interpolant& in = *drawn[k].interpolant;
            std::optional<double> extension;
            if (more_of[k] >= 0 && again[static_cast<std::size_t>(more_of[k])].interpolant)
                extension = extension_distance(in, extended[k], c.closed,
                                               *again[static_cast<std::size_t>(more_of[k])].interpolant);
            try {
                measure_truth_run(r, in, c.sample, *c.family->curve, extension);
            } catch (const std::exception& e) {  // a drawn curve no measure should fail on: the subject's defect
                r = TruthRun{.family = r.family,
                             .spacing = r.spacing,
                             .closed = r.closed,
                             .n = r.n,
                             .method = r.method,
                             .status = AttemptStatus::failed,
                             .note = std::string("measuring the curve: ") + e.what(),
                             .errors = {},
                             .shape = {},
                             .truth_shape = r.truth_shape,
                             .extensionality = {}};
            }
        });
        // family × closedness × size × subject: this subject's runs go every subjects.size() places.
        if (runs.empty()) runs.resize(cases.size() * subjects.size());
        const std::size_t s = static_cast<std::size_t>(&subject - subjects.data());
        for (std::size_t k = 0; k < cases.size(); ++k) runs[k * subjects.size() + s] = std::move(mine[k]);
    }
    return runs;
}

}  // namespace cagd::compare
