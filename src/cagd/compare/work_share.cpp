#include "cagd/compare/work_share.hpp"

#include "cagd/core/errors.hpp"

namespace cagd::compare {

void check_work_share(const WorkShare& share, const char* who) {
    if (share.count < 1 || share.index < 0 || share.index >= share.count)
        fail_input(who, "share " + std::to_string(share.index) + " of " + std::to_string(share.count) +
                            ": needs 0 <= index < count");
}

}  // namespace cagd::compare
