#pragma once
// Time profiles of the hand's commanded motions (reach, lift, shake, rock), header-only so
// that the MuJoCo check, which links no cordgrasp library, drives the same paths.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace cordgrasp {

/// Minimum-jerk profile s(τ) = 10τ³ − 15τ⁴ + 6τ⁵ on [0, 1], 0 before, 1 after.
inline double min_jerk(double tau) {
  if (tau <= 0.0) return 0.0;
  if (tau >= 1.0) return 1.0;
  return tau * tau * tau * (10.0 + tau * (-15.0 + 6.0 * tau));
}

/// ds/dτ of min_jerk.
inline double min_jerk_rate(double tau) {
  if (tau <= 0.0 || tau >= 1.0) return 0.0;
  return 30.0 * tau * tau * (1.0 - tau) * (1.0 - tau);
}

/// Peak speed of the minimum-jerk profile relative to the mean speed.
constexpr double kMinJerkPeakSpeed = 1.875;

/// sin(2πft + phase) faded in and out over a quarter period at both ends (sin² ramps), so
/// the motion starts and ends at rest; 0 outside [0, T].
inline double faded_sine(double t, double frequency_hz, double duration_s,
                         double phase_rad = 0.0) {
  if (t <= 0.0 || t >= duration_s) return 0.0;
  const double ramp = std::min(0.25 / frequency_hz, 0.5 * duration_s);
  double envelope = 1.0;
  if (t < ramp) envelope = std::pow(std::sin(0.5 * M_PI * t / ramp), 2);
  if (duration_s - t < ramp) envelope = std::pow(std::sin(0.5 * M_PI * (duration_s - t) / ramp), 2);
  return envelope * std::sin(2.0 * M_PI * frequency_hz * t + phase_rad);
}

/// Faded sines along x, y and z, each a third of a period after the last (a Lissajous path:
/// every axis goes both ways within one period, the three never peak together).
inline Eigen::Vector3d faded_lissajous(double t, double frequency_hz, double duration_s) {
  Eigen::Vector3d v;
  for (int a = 0; a < 3; ++a) v[a] = faded_sine(t, frequency_hz, duration_s, 2.0 * M_PI * a / 3.0);
  return v;
}

}  // namespace cordgrasp
