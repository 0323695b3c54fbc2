// A deterministic synthetic discharge plume (a stand-in for the OOC simulations of Binotto et al.
// 2003, section 2, which are under a non-disclosure agreement). One puff of discharge leaves a pipe
// near the surface every time step; puffs drift with a current that weakens towards the seabed,
// grow by diffusion, and settle (half of them fast like cuttings, half slowly like drilling
// fluid). A puff that reaches the seabed adds its footprint to a deposit that only ever grows.
// Voxel values: the summed Gaussian concentration times a gain, truncated to an integer and
// saturated at 255; the seabed layer shows the deposit. The result is sparse and coherent in
// space and time, as the paper's data ("temporal differences occur only in non-empty regions").
//
// Deterministic: no random numbers; the same options give the same bytes on every run.
#pragma once

#include <cstdint>

#include "reference/timevarying/timevarying_codec.h"

namespace voxref::ref {

struct PlumeOptions {
  int side = 128;  // volumes are side^3, a power of two >= 8
  int steps = 36;
  double gain = 40.0;  // concentration -> value; larger gains give less sparse volumes
};

TimeSeries dischargePlume(const PlumeOptions& options);

// The mean over all steps of the fraction of zero voxels (the paper's "spatial sparseness").
double sparseness(const TimeSeries& series);

// The plume whose sparseness is closest to `target` (e.g. 0.9965), by bisection on the gain.
// `achieved` (optional) receives the sparseness reached.
TimeSeries dischargePlumeWithSparseness(PlumeOptions options, double target, double* achieved = nullptr);

// A dense series for conformance: the gaussian_blobs field (reference/common/fields.h) drifting
// along x by one voxel per step, quantized to multiples of 32 so that large regions are
// homogeneous and the rest is refined. side^3 voxels, `steps` steps; deterministic.
TimeSeries driftingBlobs(int side, int steps);

}  // namespace voxref::ref
