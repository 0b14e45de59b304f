#pragma once
/// @file
/// The JSON curve document: a curve's Bézier pieces with what made it, enough to rebuild it (the
/// method, its parameters and the input points) and to measure it again (the pieces themselves).
///
///   {
///     "format": "cagd-curve", "format_version": 1,
///     "library_version": "0.1",            the library that wrote it (core/version.hpp)
///     "registry": "9f0c…",                 FNV-1a 64 of the registry's listing: the methods and
///                                          parameters of the library that built the curve
///                                          (methods/curve_provenance.hpp); "" when unknown
///     "method": {"name": "s-spline", "parameters": {"m": "2", …},   as typed (ParameterValues::as_text)
///                "parameter": "uniform", "closed": false},         what t is; empty "name": unknown
///     "points": [[x, y], …],               the input points ([] when unknown)
///     "dimension": 2, "degree": 4,
///     "exact": true,                       the curve's own pieces, or an approximation
///     "max_distance": 0, "tolerance": 0,   the approximation's bound and the tolerance asked for
///     "breaks": [t_0, …, t_K],             piece i on [t_i, t_{i+1}] in the method's parameter t
///     "pieces": [[[x, y], …], …]           K pieces of degree + 1 control points
///   }
///
/// The JSON surface document: a surface's Bézier patches (surface_form.hpp) with what made it.
///
///   {
///     "format": "cagd-surface", "format_version": 1, "library_version": "0.1",
///     "source": {"kind": "hosaka-tensor", "parameters": {"m": "1", …}},   what made it, as text
///     "exact": true, "conversion_error": 3e-16,    as measured by the conversion
///     "degree_u": 3, "degree_v": 3,
///     "u_breaks": [u_0, …, u_K], "v_breaks": [v_0, …, v_L],
///     "patches": [net, …]                           cell (a, b) at a + K b; a net is degree_u + 1
///   }                                               rows of degree_v + 1 points [x, y, z]
///
/// Numbers are written in the shortest form that reads back to the same double (nlohmann/json), so
/// a document read back gives the same pieces bit for bit. Writers stream, member by member: they
/// hold the curve, never its text; a non-finite number is InvalidInput naming the member.
///
/// Reading is bounded before it reads: at most kMaxDocumentBytes of text (a larger regular file is
/// refused before it is opened, a stream at the limit), the numeric arrays (points, breaks, pieces;
/// u_breaks, v_breaks, patches) streamed into flat storage, at most kMaxDocumentNumbers numbers in
/// all (8 bytes each), everything else a small DOM of at most kMaxDocumentValues values nested at
/// most 64 deep. Peak memory is the curve's numbers twice (flat, then as matrices) plus a constant.
/// Reading checks everything before using it (InvalidInput naming the document and the member or
/// the place: "not JSON (in pieces[3][1][0]): number overflow parsing '1e400'"): the format and its
/// version, dimension 2 or 3, 1 ≤ degree ≤ 31, 1 to 10^7 pieces, breaks increasing with a finite
/// span, every piece of degree + 1 points of `dimension` finite coordinates, and pieces that join:
/// piece i starts where piece i − 1 ends (first_unjoined_piece, bspline_form.hpp).
#include <cstdint>
#include <istream>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "cagd/core/points.hpp"
#include "cagd/export/bezier_form.hpp"
#include "cagd/export/surface_form.hpp"

namespace cagd::exports {

/// The readers' limits (see above): a 10^6-point space curve's document of cubic pieces is about
/// 300 MB and 1.5·10^7 numbers.
inline constexpr std::uint64_t kMaxDocumentBytes = std::uint64_t{1} << 30;  ///< 1 GiB of text
inline constexpr long long kMaxDocumentNumbers = 1LL << 25;                 ///< 256 MiB as doubles
inline constexpr long long kMaxDocumentValues = 100'000;  ///< strings, booleans, … outside the arrays
inline constexpr int kMaxDocumentDegree = 31;             ///< a curve document's pieces
inline constexpr long kMaxDocumentPieces = 10'000'000;    ///< a curve document's pieces
inline constexpr int kMaxSurfaceDocumentDegree = 1000;    ///< a surface document's degrees

/// Parameter names and their values, as text.
using ParameterText = std::map<std::string, std::string>;

/// What made a curve, as plain data (all optional: a curve from elsewhere has an empty method
/// name). methods::method_provenance fills it for a method of the registry.
struct CurveProvenance {
    std::string method{};        ///< registry name
    ParameterText parameters{};  ///< its parameter values as text
    std::string parameter{};     ///< what the curve's parameter t is (MethodClaims::parameter)
    bool closed = false;         ///< a closed curve
    PointList points{};          ///< the input points (0 rows when unknown)
    std::string registry{};      ///< the fingerprint of the registry that built it ("" when unknown)
};

/// A curve document read back.
struct CurveDocument {
    CurveProvenance provenance;   ///< what made it
    BezierForm form;              ///< its pieces, exactness and error bound
    std::string library_version;  ///< as written
};

/// Writes the document of `form` and `provenance` (see above) to `out`.
void write_curve_json(std::ostream& out, const BezierForm& form, const CurveProvenance& provenance);
/// Reads a document (see above); `source` names it in messages. InvalidInput for anything invalid.
CurveDocument read_curve_json(std::istream& in, const std::string& source);
/// The same from a file path.
CurveDocument read_curve_json_file(const std::string& path);

/// What made a surface.
struct SurfaceProvenance {
    std::string kind{};          ///< e.g. hosaka-tensor, hosaka-cartesian, hosaka-coons, typical-surface
    ParameterText parameters{};  ///< its inputs as text
};

/// A surface document read back.
struct SurfaceDocument {
    SurfaceProvenance provenance;  ///< what made it
    SurfaceForm form;              ///< its patches, exactness and conversion error
    std::string library_version;   ///< as written
};

/// Writes the surface document of `form` and `provenance` (see above) to `out`.
void write_surface_json(std::ostream& out, const SurfaceForm& form, const SurfaceProvenance& provenance);
/// Reads a surface document, bounded as a curve document is: format and version, 1 ≤ degrees ≤ 1000,
/// breaks increasing with a finite span (at most 100001), at most 10^7 control points, one net of
/// finite points per cell; InvalidInput naming the document and the member otherwise.
SurfaceDocument read_surface_json(std::istream& in, const std::string& source);
/// The same from a file path.
SurfaceDocument read_surface_json_file(const std::string& path);

}  // namespace cagd::exports
