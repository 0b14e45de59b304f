// libFuzzer target: the CSV point reader (core/point_csv) on arbitrary bytes.
// Contract checked: it returns a point list (1+ rows, 2 or 3 columns, every value finite) or throws
// cagd::InvalidInput; nothing else escapes, and ASan/UBSan see no memory error or undefined
// behaviour. Seed corpus: tests/fuzz/corpus/point_reader.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "core/point_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        const cagd::PointList p = cagd::read_points_csv(in, "fuzz");
        if (p.rows() < 1 || (p.cols() != 2 && p.cols() != 3) || !p.allFinite()) std::abort();
    } catch (const cagd::InvalidInput&) {}
    return 0;
}
