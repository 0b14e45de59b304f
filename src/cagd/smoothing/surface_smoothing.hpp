#pragma once
/// @file
/// Hosaka's surface smoothing (hosaka, sections 6–7, eq 53–60): gridded data a(x_i, y_j) pulled by
/// springs onto an elastic net or an elastic plate, one header per method:
///   smoothing/elastic_net.hpp              the elastic net (eq 53–54) and approximation 2 (iv)
///   smoothing/plate_smoothing.hpp          the plate energies (eq 55–59) and method (i)
///   smoothing/boundary_plate_smoothing.hpp method (ii): eq (31) between two boundary lines
///   smoothing/window_smoothing.hpp         approximation 1 (eq 60): 5 × 5 windows
#include "cagd/smoothing/boundary_plate_smoothing.hpp"
#include "cagd/smoothing/elastic_net.hpp"
#include "cagd/smoothing/plate_smoothing.hpp"
#include "cagd/smoothing/window_smoothing.hpp"
