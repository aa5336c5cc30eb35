#include "dynamics/response.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace tbridge {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

void CheckSignal(const Eigen::VectorXd& signal, double dt, int min_samples) {
  if (signal.size() < min_samples) {
    throw std::invalid_argument("time history: need at least " + std::to_string(min_samples) +
                                " samples, got " + std::to_string(signal.size()));
  }
  if (!(dt > 0) || !std::isfinite(dt)) throw std::invalid_argument("time history: dt must be > 0");
  if (!signal.allFinite()) throw std::invalid_argument("time history: non-finite sample");
}

FrequencyEstimate FromHz(double hz) {
  FrequencyEstimate e;
  e.frequency_hz = hz;
  e.omega_rad_s = kTwoPi * hz;
  e.period_s = hz > 0 ? 1 / hz : 0;
  return e;
}

// Least-squares fit of c + a cos(wt) + b sin(wt): returns the explained sum of squares and
// the amplitude sqrt(a^2 + b^2).
std::pair<double, double> SinusoidFit(const Eigen::VectorXd& y, double dt, double hz) {
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d aty = Eigen::Vector3d::Zero();
  const double w = kTwoPi * hz * dt;
  for (Eigen::Index k = 0; k < y.size(); ++k) {
    const Eigen::Vector3d row(1.0, std::cos(w * k), std::sin(w * k));
    ata += row * row.transpose();
    aty += row * y(k);
  }
  const Eigen::Vector3d coef = ata.ldlt().solve(aty);
  return {coef.dot(aty), std::hypot(coef(1), coef(2))};
}

}  // namespace

void Fft(std::vector<std::complex<double>>& data) {
  const size_t n = data.size();
  if (n == 0 || (n & (n - 1)) != 0) {
    throw std::invalid_argument("FFT: size " + std::to_string(n) + " is not a power of 2");
  }
  for (size_t i = 1, j = 0; i < n; ++i) {  // bit-reversal permutation
    size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(data[i], data[j]);
  }
  for (size_t len = 2; len <= n; len <<= 1) {
    const std::complex<double> step = std::polar(1.0, -kTwoPi / static_cast<double>(len));
    for (size_t start = 0; start < n; start += len) {
      std::complex<double> w = 1.0;
      for (size_t k = 0; k < len / 2; ++k) {
        const std::complex<double> odd = w * data[start + k + len / 2];
        data[start + k + len / 2] = data[start + k] - odd;
        data[start + k] += odd;
        w *= step;
      }
    }
  }
}

Spectrum AmplitudeSpectrum(const Eigen::VectorXd& signal, double dt,
                           const SpectrumOptions& options) {
  CheckSignal(signal, dt, 2);
  if (options.padding < 1) throw std::invalid_argument("spectrum: padding must be >= 1");
  const Eigen::Index n = signal.size();
  size_t size = 1;
  while (size < static_cast<size_t>(n) * static_cast<size_t>(options.padding)) size <<= 1;
  const double mean = signal.mean();
  std::vector<std::complex<double>> data(size, 0.0);
  double gain = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    // Symmetric Hann: both ends of the record taper to zero.
    const double w =
        options.hann ? 0.5 - 0.5 * std::cos(kTwoPi * k / static_cast<double>(n - 1)) : 1.0;
    data[k] = w * (signal(k) - mean);
    gain += w;
  }
  Fft(data);
  const size_t half = size / 2;
  Spectrum s;
  s.frequency_hz.resize(half + 1);
  s.amplitude.resize(half + 1);
  for (size_t k = 0; k <= half; ++k) {
    s.frequency_hz(k) = static_cast<double>(k) / (static_cast<double>(size) * dt);
    s.amplitude(k) = (k == 0 || k == half ? 1.0 : 2.0) * std::abs(data[k]) / gain;
  }
  return s;
}

FrequencyEstimate DominantFrequency(const Eigen::VectorXd& signal, double dt,
                                    const SpectrumOptions& options) {
  const Spectrum s = AmplitudeSpectrum(signal, dt, options);
  const double nyquist = 0.5 / dt;
  const double max_hz = options.max_hz > 0 ? std::min(options.max_hz, nyquist) : nyquist;
  Eigen::Index best = -1;
  for (Eigen::Index k = 1; k < s.frequency_hz.size(); ++k) {
    const double f = s.frequency_hz(k);
    if (f <= options.min_hz || f > max_hz) continue;
    if (best < 0 || s.amplitude(k) > s.amplitude(best)) best = k;
  }
  if (best < 0)
    throw std::invalid_argument("dominant frequency: the search band holds no frequency");
  if (s.amplitude(best) == 0)
    throw std::invalid_argument("dominant frequency: the signal is constant");
  const double record = static_cast<double>(signal.size()) * dt;
  FrequencyEstimate e = FromHz(s.frequency_hz(best));
  e.amplitude = s.amplitude(best);
  if (options.refine) {
    // Golden-section search for the best-fitting sinusoid within a quarter of the record's
    // resolution 1/T of the grid peak: inside the fit's main lobe, so one maximum.
    const double half_width = 0.25 / record;
    // Fit the centred record: with the mean left in, the constant dominates the explained sum
    // of squares and a small oscillation on a large offset loses its precision.
    const Eigen::VectorXd centred = signal.array() - signal.mean();
    double lo = std::max(e.frequency_hz - half_width, 0.0),
           hi = std::min(e.frequency_hz + half_width, nyquist);
    const double ratio = 0.5 * (std::sqrt(5.0) - 1);
    double a = hi - ratio * (hi - lo), b = lo + ratio * (hi - lo);
    double fa = SinusoidFit(centred, dt, a).first, fb = SinusoidFit(centred, dt, b).first;
    while (hi - lo > 1e-12 * hi) {
      if (fa < fb) {
        lo = a;
        a = b;
        fa = fb;
        b = lo + ratio * (hi - lo);
        fb = SinusoidFit(centred, dt, b).first;
      } else {
        hi = b;
        b = a;
        fb = fa;
        a = hi - ratio * (hi - lo);
        fa = SinusoidFit(centred, dt, a).first;
      }
    }
    const double hz = 0.5 * (lo + hi);
    e = FromHz(hz);
    e.amplitude = SinusoidFit(centred, dt, hz).second;
  }
  e.cycles = record * e.frequency_hz;
  return e;
}

FrequencyEstimate MeanPeriodFromCrossings(const Eigen::VectorXd& signal, double dt,
                                          const CrossingOptions& options) {
  CheckSignal(signal, dt, 3);
  if (!(options.hysteresis >= 0)) throw std::invalid_argument("crossings: hysteresis must be >= 0");
  const Eigen::VectorXd y = signal.array() - signal.mean();
  const double rms = std::sqrt(y.squaredNorm() / static_cast<double>(y.size()));
  const double band = options.hysteresis * rms;
  // side: +1 once the signal has been above +band, -1 below -band; a crossing is the last
  // mean-level sign change before the side flips.
  int side = 0;
  double last_crossing = 0, first = 0, last = 0;
  int crossings = 0;
  double swing = 0, high = 0, low = 0;
  for (Eigen::Index k = 1; k < y.size(); ++k) {
    if ((y(k - 1) < 0) != (y(k) < 0)) {
      last_crossing = dt * (static_cast<double>(k - 1) + y(k - 1) / (y(k - 1) - y(k)));
    }
    high = std::max(high, y(k));
    low = std::min(low, y(k));
    const int now = y(k) > band ? 1 : (y(k) < -band ? -1 : side);
    if (now != side && side != 0) {
      if (crossings == 0) first = last_crossing;
      last = last_crossing;
      ++crossings;
      swing += (side > 0 ? high : -low);
      high = low = 0;
    }
    side = now;
  }
  if (crossings < 3) {
    throw std::invalid_argument("crossings: " + std::to_string(crossings) +
                                " mean-level crossings, need 3 (one full period)");
  }
  FrequencyEstimate e = FromHz((crossings - 1) / (2 * (last - first)));
  e.amplitude = swing / crossings;
  e.cycles = 0.5 * (crossings - 1);
  return e;
}

double TrendShare(const Eigen::VectorXd& signal) {
  const Eigen::Index n = signal.size();
  if (n < 2) return 0;
  // Sample index about its mean against the signal about its mean: slope = Sty / Stt.
  const Eigen::ArrayXd t = Eigen::ArrayXd::LinSpaced(n, 0.0, static_cast<double>(n - 1)) -
                           0.5 * static_cast<double>(n - 1);
  const Eigen::ArrayXd y = signal.array() - signal.mean();
  const double total = y.square().sum();
  if (!(total > 0)) return 0;
  const double sty = (t * y).sum();
  return std::min(1.0, sty * sty / (t.square().sum() * total));
}

FrequencyReading MeasureFrequency(const Eigen::VectorXd& signal, double dt,
                                  const SpectrumOptions& options) {
  FrequencyReading out;
  char text[200];
  // Equal samples are no motion, though their mean's rounding leaves DominantFrequency a
  // spectrum of last-place noise to find a peak in.
  if (signal.size() > 0 && signal.maxCoeff() == signal.minCoeff()) {
    out.note = "the record is constant: nothing moves";
    return out;
  }
  try {
    const FrequencyEstimate e = DominantFrequency(signal, dt, options);
    const double trend = TrendShare(signal);
    const double periods = static_cast<double>(signal.size() - 1) * dt * e.frequency_hz;
    if (trend > kMaxTrendShare) {
      std::snprintf(
          text, sizeof text,
          "the motion is a drift, not an oscillation: a straight line through the record explains "
          "%.3g %% of its variance (more than %g %%)",
          100 * trend, 100 * kMaxTrendShare);
      out.note = text;
    } else if (periods < kMinPeriodsForFrequency) {
      std::snprintf(
          text, sizeof text,
          "the record (%.6g s) holds %.3g periods of its strongest component (%.6g Hz), fewer "
          "than %g: a longer run would show whether it oscillates",
          static_cast<double>(signal.size() - 1) * dt, periods, e.frequency_hz,
          kMinPeriodsForFrequency);
      out.note = text;
    } else {
      out.estimate = e;
    }
  } catch (const std::invalid_argument& error) {
    out.note = error.what();
  }
  return out;
}

FrequencyEstimate DeckFrequency(const Eigen::MatrixXd& deck_vertical, double dt, double duration,
                                const SpectrumOptions& options) {
  return DominantFrequency(DeckSignal(deck_vertical, dt, duration), dt, options);
}

Eigen::Index SamplesWithin(Eigen::Index samples, double dt, double duration) {
  if (samples == 0) throw std::invalid_argument("deck frequency: no samples");
  if (!(duration > 0)) throw std::invalid_argument("deck frequency: duration must be > 0");
  if (!(dt > 0)) throw std::invalid_argument("deck frequency: dt must be > 0");
  return std::min<Eigen::Index>(
      samples, static_cast<Eigen::Index>(std::floor(duration / dt * (1 + 1e-12))) + 1);
}

Eigen::VectorXd DeckSignal(const Eigen::MatrixXd& deck_vertical, double dt, double duration) {
  if (deck_vertical.size() == 0) throw std::invalid_argument("deck frequency: no samples");
  return deck_vertical.topRows(SamplesWithin(deck_vertical.rows(), dt, duration)).rowwise().sum();
}

}  // namespace tbridge
