#include "cagd/compare/peer_truths.hpp"

#include <string>

#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"

namespace cagd::compare {

std::vector<TruthRun> subject_truth_runs(const std::vector<CurveSubject>& subjects, const std::vector<int>& sizes,
                                         int threads) {
    check_truth_sizes(sizes, "cagd::compare::subject_truth_runs");
    if (threads <= 0) threads = hardware_threads();
    std::vector<const TruthFamily*> families;
    for (const TruthFamily& f : truth_families()) families.push_back(&f);
    const std::vector<TruthCase> cases = truth_cases(families, {TruthSpacing::uniform}, sizes);
    std::vector<TruthSample> samples(cases.size());
    parallel_for(static_cast<long>(cases.size()), threads, [&](long k) {
        const TruthCase& c = cases[static_cast<std::size_t>(k)];
        samples[static_cast<std::size_t>(k)] = truth_samples(*c.family, c.n, c.spacing, c.closed);
    });
    std::vector<CurveRequest> requests;
    for (std::size_t k = 0; k < cases.size(); ++k) requests.push_back({samples[k].points, cases[k].closed});
    std::vector<TruthRun> runs;
    for (const CurveSubject& subject : subjects) {
        const std::vector<DrawnCurve> drawn = subject.draw(requests);
        // The extensions (extensionality()) of the curves drawn, in a second batch.
        std::vector<ExtendedPoints> extended(cases.size());
        std::vector<CurveRequest> more;
        std::vector<long> more_of(cases.size(), -1);
        for (std::size_t k = 0; k < cases.size(); ++k) {
            if (!drawn[k].interpolant) continue;
            extended[k] = extended_points(samples[k].points, cases[k].closed, *drawn[k].interpolant);
            more_of[k] = static_cast<long>(more.size());
            more.push_back({extended[k].points, cases[k].closed});
        }
        const std::vector<DrawnCurve> again = more.empty() ? std::vector<DrawnCurve>{} : subject.draw(more);
        std::vector<TruthRun> mine(cases.size());
        parallel_for(static_cast<long>(cases.size()), threads, [&](long index) {
            const auto k = static_cast<std::size_t>(index);
            const TruthCase& c = cases[k];
            const TruthSample& sample = samples[k];
            TruthRun& r = mine[k];
            r.family = c.family->name, r.spacing = c.spacing, r.closed = c.closed, r.n = c.n;
            r.method = subject.name;
            r.truth_shape = shape_measures(*c.family->curve, sample.params, c.closed);
            r.status = drawn[k].status;
            r.note = drawn[k].note;
            if (!drawn[k].interpolant) return;
            const methods::Interpolant& in = *drawn[k].interpolant;
            std::optional<double> extension;
            if (more_of[k] >= 0 && again[static_cast<std::size_t>(more_of[k])].interpolant)
                extension = extension_distance(in, extended[k], c.closed,
                                               *again[static_cast<std::size_t>(more_of[k])].interpolant);
            try {
                measure_truth_run(r, in, sample, *c.family->curve, extension);
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
