// Periods and frequencies from sampled time histories (uniform step dt, sample k at t = k dt).
//
// Two independent estimators:
// - DominantFrequency: the highest peak of the amplitude spectrum (mean removed, Hann window,
//   zero-padded radix-2 FFT), refined by maximising the least-squares fit of
//   c + a cos(wt) + b sin(wt) near that peak. The fit is exact for a pure sinusoid whatever
//   the record length, so unlike a parabola through FFT bins it carries no bias from the
//   negative-frequency image or from the window.
// - MeanPeriodFromCrossings: mean spacing of mean-level crossings (with hysteresis against
//   noise), linearly interpolated between samples.
// DeckFrequency is the measurement that reproduces the paper's Table 5 (SPEC.md §9): the
// dominant spectral peak of the summed vertical displacement of the deck nodes over 0-1 s.
#pragma once

#include <Eigen/Core>
#include <complex>
#include <optional>
#include <string>
#include <vector>

namespace tbridge {

struct FrequencyEstimate {
  double omega_rad_s = 0;   // 2 pi f [rad/s]
  double frequency_hz = 0;  // f [Hz]
  double period_s = 0;      // 1 / f [s]
  double amplitude = 0;     // sinusoid amplitude at f (spectral) or half the mean swing
                            // (crossings), in the signal's unit
  double cycles = 0;        // periods spanned by the record (spectral) or counted (crossings)
};

struct SpectrumOptions {
  int padding = 8;     // FFT length >= padding x samples (rounded up to a power of 2), >= 1
  bool hann = true;    // Hann window for the peak search (lower leakage than rectangular)
  bool refine = true;  // least-squares refinement; false returns the padded FFT grid peak
  double min_hz = 0;   // search band [Hz]; frequencies at or below min_hz are skipped,
  double max_hz = 0;   // and max_hz <= 0 means up to Nyquist 1/(2 dt)
};

struct Spectrum {
  Eigen::VectorXd frequency_hz;  // 0 .. Nyquist on the padded grid [Hz]
  Eigen::VectorXd amplitude;     // single-sided sinusoid amplitude, window gain removed
};

// In-place radix-2 FFT, X_k = sum_n x_n exp(-2 pi i k n / N). Throws std::invalid_argument
// unless the size is a power of 2 (1 included).
void Fft(std::vector<std::complex<double>>& data);

// Amplitude spectrum of the mean-removed signal. Throws std::invalid_argument for fewer than
// 2 samples, dt <= 0, padding < 1 or non-finite samples.
Spectrum AmplitudeSpectrum(const Eigen::VectorXd& signal, double dt,
                           const SpectrumOptions& options = {});

// Dominant frequency of `signal` (see the top). Throws std::invalid_argument as above, for an
// empty search band, or when the mean-removed signal is zero.
FrequencyEstimate DominantFrequency(const Eigen::VectorXd& signal, double dt,
                                    const SpectrumOptions& options = {});

struct CrossingOptions {
  // A crossing counts only after the signal has gone beyond +-hysteresis x RMS on the far side
  // of the mean; 0 counts every sign change.
  double hysteresis = 0.5;
};

// Mean period from the mean-level crossings, up and down: T = 2 (t_last - t_first) /
// (crossings - 1). Throws std::invalid_argument for bad input as above or fewer than 3
// crossings (less than one period).
FrequencyEstimate MeanPeriodFromCrossings(const Eigen::VectorXd& signal, double dt,
                                          const CrossingOptions& options = {});

// A record shows a frequency only when it holds at least this many periods of it: one period
// cannot tell an oscillation from a single swing, and the spectral peak of a record shorter
// than two periods lies within two resolution steps 1/T of zero, where the mean removal and
// the window bend it most.
inline constexpr double kMinPeriodsForFrequency = 2;
// A motion is a drift, not an oscillation, when a straight line through the record explains
// more than this share of its variance about its mean. A sine of N whole periods gives a
// line 6 cos^2(phase) / (pi^2 N^2) of it, at most 0.15 at N = 2 (and no more for any N >= 2,
// whole or not): a sine long enough for a frequency is never taken for a drift.
inline constexpr double kMaxTrendShare = 0.5;

// The share of the variance of `signal` about its mean that the least-squares straight line
// through it explains (R^2 of a linear fit, in [0, 1]); 0 for a constant signal.
double TrendShare(const Eigen::VectorXd& signal);

// The dominant frequency of `signal` (DominantFrequency) when the record shows an oscillation
// at it; none, with the reason in `note`, where the motion is a drift (TrendShare above
// kMaxTrendShare: a quasi-static response, a deck sinking under a load applied slowly), where
// the record spans fewer than kMinPeriodsForFrequency periods of it, where every sample is
// the same, or where DominantFrequency throws (its reason). Throws nothing.
struct FrequencyReading {
  std::optional<FrequencyEstimate> estimate;
  std::string note;  // why there is none; empty when there is one
};
FrequencyReading MeasureFrequency(const Eigen::VectorXd& signal, double dt,
                                  const SpectrumOptions& options = {});

// The paper's measurement: `deck_vertical` is samples x deck nodes (vertical displacement or
// position, the mean is removed anyway), row k at t = k dt; the rows with t <= duration [s]
// are summed across the nodes and passed to DominantFrequency. Throws std::invalid_argument
// for an empty matrix, duration <= 0, or as DominantFrequency.
FrequencyEstimate DeckFrequency(const Eigen::MatrixXd& deck_vertical, double dt,
                                double duration = 1.0, const SpectrumOptions& options = {});
// The signal DeckFrequency measures: the rows with t <= duration, summed across the nodes.
// `simulate` also passes it to MeanPeriodFromCrossings, the second estimate in its summary:
// where the motion is periodic the two agree, where strings go slack they part. Throws
// std::invalid_argument for an empty matrix, dt <= 0 or duration <= 0.
Eigen::VectorXd DeckSignal(const Eigen::MatrixXd& deck_vertical, double dt, double duration);
// How many of `samples` taken every dt from t = 0 have t <= duration (with a relative slack
// for round-off in k dt). Throws std::invalid_argument for no samples, dt <= 0 or duration <= 0.
Eigen::Index SamplesWithin(Eigen::Index samples, double dt, double duration);

}  // namespace tbridge
