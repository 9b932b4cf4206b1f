#include "cells2d/avalanches.hpp"

#include <algorithm>
#include <cmath>

namespace cmp::cells2d {

double first_outflow(const PressureSeries& s) {
  for (std::size_t k = 1; k < s.time.size(); ++k)
    if (s.left[k] > s.left[k - 1]) return s.time[k];
  return s.time.empty() ? 0.0 : s.time.back();
}

std::vector<Avalanche> find_avalanches(const PressureSeries& s, double merge, double from) {
  if (from < 0) from = first_outflow(s);
  const std::size_t n = s.time.size();
  // Runs of outflow samples, joined across gaps shorter than merge: [first, last] sample indices.
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (std::size_t k = 1; k < n; ++k) {
    if (s.time[k] < from || s.left[k] <= s.left[k - 1]) continue;
    if (!runs.empty() && s.time[k] - s.time[runs.back().second] <= merge)
      runs.back().second = k;
    else
      runs.emplace_back(k, k);
  }
  std::vector<Avalanche> out;
  std::size_t previous_end = 0;
  for (std::size_t e = 0; e < runs.size(); ++e) {
    const auto [first, last] = runs[e];
    Avalanche a;
    a.start = s.time[first], a.end = s.time[last];
    a.size = s.left[last] - s.left[first - 1];
    // Peak: the highest pressure since the previous event ended (or the window began).
    std::size_t lo = e == 0 ? first - 1 : previous_end;
    while (e == 0 && lo > 0 && s.time[lo - 1] >= from) --lo;
    std::size_t peak = lo;
    for (std::size_t k = lo; k <= first; ++k)
      if (s.pressure[k] > s.pressure[peak]) peak = k;
    // Base: the lowest pressure from the start to the next event's start (or the end).
    const std::size_t hi = e + 1 < runs.size() ? runs[e + 1].first - 1 : n - 1;
    std::size_t base = first;
    for (std::size_t k = first; k <= hi; ++k)
      if (s.pressure[k] < s.pressure[base]) base = k;
    a.peak_time = s.time[peak], a.peak = s.pressure[peak];
    a.base_time = s.time[base], a.base = s.pressure[base];
    a.drop = a.peak - a.base;
    if (a.base_time > a.peak_time) a.drop_rate = a.drop / (a.base_time - a.peak_time);
    if (!out.empty() && a.peak_time > out.back().base_time)
      a.rise_rate = (a.peak - out.back().base) / (a.peak_time - out.back().base_time);
    out.push_back(a);
    previous_end = last;
  }
  return out;
}

AvalancheSummary summarise(const PressureSeries& s, const std::vector<Avalanche>& events, double from) {
  AvalancheSummary m;
  if (from < 0) from = first_outflow(s);
  m.from = from;
  m.to = s.time.empty() ? 0.0 : s.time.back();
  // Time average by the trapezoid rule over the window.
  double integral = 0, span = 0;
  for (std::size_t k = 1; k < s.time.size(); ++k) {
    if (s.time[k - 1] < from) continue;
    const double dt = s.time[k] - s.time[k - 1];
    integral += 0.5 * (s.pressure[k] + s.pressure[k - 1]) * dt, span += dt;
  }
  m.mean_pressure = span > 0 ? integral / span : 0.0;
  m.events = static_cast<long>(events.size());
  if (events.empty()) return m;
  long rises = 0, drops = 0;
  for (const Avalanche& a : events) {
    m.mean_drop += a.drop, m.mean_size += static_cast<double>(a.size);
    if (a.rise_rate > 0) m.mean_rise_rate += a.rise_rate, ++rises;
    if (a.drop_rate > 0) m.mean_drop_rate += a.drop_rate, ++drops;
  }
  m.mean_drop /= static_cast<double>(events.size());
  m.mean_size /= static_cast<double>(events.size());
  if (rises) m.mean_rise_rate /= static_cast<double>(rises);
  if (drops) m.mean_drop_rate /= static_cast<double>(drops);
  if (m.mean_rise_rate > 0) m.rate_ratio = m.mean_drop_rate / m.mean_rise_rate;
  // The tail: excesses x = (drop - mean)/mean of the drops above the mean, against the
  // exponential of the same mean.
  std::vector<double> excess;
  for (const Avalanche& a : events)
    if (a.drop > m.mean_drop && m.mean_drop > 0) excess.push_back((a.drop - m.mean_drop) / m.mean_drop);
  m.tail_events = static_cast<long>(excess.size());
  if (excess.empty()) return m;
  std::sort(excess.begin(), excess.end());
  double sum = 0;
  for (double x : excess) sum += x;
  m.tail_scale = sum / static_cast<double>(excess.size());
  const double count = static_cast<double>(excess.size());
  for (std::size_t i = 0; i < excess.size(); ++i) {
    const double model = 1 - std::exp(-excess[i] / m.tail_scale);
    m.tail_ks = std::max({m.tail_ks, std::abs(model - static_cast<double>(i) / count),
                          std::abs(model - static_cast<double>(i + 1) / count)});
  }
  return m;
}

}  // namespace cmp::cells2d
