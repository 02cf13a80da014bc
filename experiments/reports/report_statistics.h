// The report's figures of solved against time (issue 14): a cactus plot and a Dolan-More
// performance profile of a suite's problem (toy and WCSP) runs, as inline SVG.
//
// The data are time_profiles.h's, the same as OUT/cactus.csv and OUT/profiles.csv:
//  - cactus plot: runs solved (y) against time (x): each solver's curve steps up by one at
//    the time of each of its solved runs, up to the time limit; the time axis is
//    logarithmic when the solved times span a factor of 10 or more, else linear from 0;
//  - performance profile: rho_s(tau), the fraction of instances a solver solves within a
//    factor tau of the best solver on that instance (y, 0..1) against tau (x, logarithmic
//    from 1); the curve at tau = 1 is how often the solver is the fastest, its height at the
//    right edge how often it solves at all.
// Hand-written SVG text (axes, ticks, labels, one polyline per solver, a legend) keeps the
// report one self-contained file with no scripts.
#pragma once

#include <string>

#include "sightline/experiments/suite/suite.h"
#include "sightline/experiments/suite/suite_results.h"
#include "sightline/experiments/reports/time_profiles.h"

namespace sightline::experiments {

struct StatisticsFigureOptions {
  int width = 640;  // pixels, each figure
  int height = 300;
};

// One <svg> element each, with a viewBox of 0 0 width height; every coordinate inside it.
std::string cactus_svg(const TimeProfiles& profiles, const StatisticsFigureOptions& options = {});
std::string performance_profile_svg(const TimeProfiles& profiles,
                                    const StatisticsFigureOptions& options = {});

// The report section of anytime curves: per problem, each solver's best feasible cost over
// time (median over seeds, interquartile band; from out_dir/runs/<id>.anytime.csv) and a
// box plot of its final costs over seeds; empty when no problem run left a trajectory.
std::string anytime_report_section(const Suite& suite, const SuiteOutcome& outcome,
                                   const std::string& out_dir,
                                   const StatisticsFigureOptions& options = {});

// The report section ("Solved against time": a short explanation and both figures); empty
// when the suite has no problem runs.
std::string statistics_report_section(const Suite& suite, const SuiteOutcome& outcome,
                                      const StatisticsFigureOptions& options = {});

}  // namespace sightline::experiments
