#pragma once
// Avalanches of the chamber's time series (thesis Fig. 2.2d-e, S2.10, S2.13): the pressure rises
// slowly while the outlet is clogged and drops when cells flush out. An outflow event is a run
// of samples in which cells leave, samples less than `merge` apart joined into one. For each:
//   peak  the highest pressure between the previous event and this one's start,
//   base  the lowest pressure from this event's start to the next event's start,
//   drop  peak - base (the thesis's "pressure change from the peak pressure prior to an outflow
//         event to the base pressure just after the event"),
//   rise rate  (peak - previous base) / (time from the previous base to the peak),
//   drop rate  drop / (time from the peak to the base),
//   size  the cells that left during the event.
// The summary fits the tail of the drops larger than their mean by an exponential (maximum
// likelihood: the mean excess), with the Kolmogorov-Smirnov distance of the excesses from it.
#include <string>
#include <vector>

namespace cmp::cells2d {

struct PressureSeries {
  std::vector<double> time, pressure;
  std::vector<long> left;  // cells removed so far
};

struct Avalanche {
  double start = 0, end = 0;           // first and last sample with outflow [1/gamma0]
  double peak_time = 0, peak = 0;      // [1/gamma0], [k]
  double base_time = 0, base = 0;
  double drop = 0;
  double rise_rate = 0;                // [k gamma0]; 0 for the first event (no previous base)
  double drop_rate = 0;
  long size = 0;                       // cells
};

struct AvalancheSummary {
  double from = 0, to = 0;             // the window analysed [1/gamma0]
  double mean_pressure = 0;            // time average over the window [k]
  long events = 0;
  double mean_drop = 0, mean_size = 0;
  double mean_rise_rate = 0, mean_drop_rate = 0, rate_ratio = 0;  // ratio: drop over rise
  long tail_events = 0;                // drops larger than the mean drop
  double tail_scale = 0;               // mean excess over the mean drop, in units of the mean drop
  double tail_ks = 0;                  // KS distance of the excesses from that exponential
};

// Outflow events of the samples at t >= from (from < 0: from the first cell leaving).
std::vector<Avalanche> find_avalanches(const PressureSeries& series, double merge, double from);
AvalancheSummary summarise(const PressureSeries& series, const std::vector<Avalanche>& events, double from);
// The first time a cell has left (the end of the filling transient), or the series' end.
double first_outflow(const PressureSeries& series);

}  // namespace cmp::cells2d
