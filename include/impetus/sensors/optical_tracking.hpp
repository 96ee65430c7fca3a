// Optical tracking (ch. 25): velocity and acceleration from a tracked position series, the
// hand-off of a thrown object to the projectile models, and depth from stereo disparity.
//
// A camera tracker (Kinect, OpenCV on one or two cameras) reports positions (x, y, z) at times
// t, 20-30 times a second. Differentiating them (the reverse of the book's integrators) gives
// the velocity and acceleration; finite_difference.hpp has the formulas and their orders,
// savitzky_golay.hpp the smoothing differentiator for noisy data. The book's hand-off: track the
// ball in the hand until it leaves it, then give the release position, velocity and acceleration
// to the projectile simulator as its initial conditions.
//
// Depth from two rectified cameras a baseline B apart, focal length f in pixels: a point at depth
// Z appears d = f B / Z pixels apart in the two images, so Z = f B / d (OpenCV's
// reprojectImageTo3D does this per pixel).
#pragma once

#include <impetus/math/vec3.hpp>

#include <span>
#include <vector>

namespace impetus::sensors {

struct TrackSample {
  double time = 0.0; ///< s
  Vec3d position;    ///< m
};

struct TrackState {
  double time = 0.0;
  Vec3d position;     ///< m (smoothed with savitzkyGolay, else as sampled)
  Vec3d velocity;     ///< m/s
  Vec3d acceleration; ///< m/s^2
};

enum class TrackMethod {
  backward,      ///< real time: v from the last two samples, a from the last three (O(h); lags)
  central,       ///< offline: 3-point central differences inside (uneven steps allowed, O(h^2)),
                 ///< 3-point one-sided second-order formulas at the two ends
  savitzkyGolay, ///< offline, noisy data: Savitzky-Golay fits (even steps)
};

struct TrackOptions {
  TrackMethod method = TrackMethod::central;
  int halfWidth = 3;           ///< Savitzky-Golay window 2m + 1
  int order = 2;               ///< Savitzky-Golay polynomial degree (>= 2 for acceleration)
  double evenTolerance = 1e-6; ///< relative spread of the steps still taken as even (Savitzky-Golay)
};

/// The state at every sample. Needs at least 3 samples (2m + 1 for Savitzky-Golay), times
/// strictly increasing. Backward: the first sample gets v = a = 0, the second a = 0. Throws
/// impetus::Error naming "samples" (too few, not finite, time not increasing or, for
/// Savitzky-Golay, uneven) or the option.
[[nodiscard]] std::vector<TrackState> differentiateTrack(std::span<const TrackSample> samples,
                                                         const TrackOptions& options = {});

/// The hand-off: the state at the last sample from past samples only (what a game knows at the
/// moment of release). Backward differences, or with savitzkyGolay the fit over the last 2m + 1
/// samples evaluated at the newest one (no lag, less noise than backward).
[[nodiscard]] TrackState releaseState(std::span<const TrackSample> samples, const TrackOptions& options = {});

/// Z = f B / d, m: focal length f > 0 px, baseline B > 0 m, disparity d > 0 px (fields
/// "focalPixels", "baseline", "disparity").
[[nodiscard]] double depthFromDisparity(double focalPixels, double baseline, double disparity);

} // namespace impetus::sensors
