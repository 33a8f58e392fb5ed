#include "cli/calibration_flags.hpp"

namespace dtwin::cli {

void CalibrationFlags::addTo(CLI::App* app, unsigned which) {
  if (which & kSizes) {
    app->add_option(
           "--lhs-points", lhs_points,
           "Design points of the first Latin hypercube (default: the study's sizes.lhs_points)")
        ->check(CLI::Range(2L, 10000000L));
    app->add_option("--iterations", iterations,
                    "Gibbs iterations incl. burn-in (default: sizes.gibbs_iterations)")
        ->check(CLI::Range(1L, 100000000L));
    app->add_option("--burn-in", burn_in, "Gibbs burn-in (default: sizes.gibbs_burn_in)")
        ->check(CLI::Range(0L, 100000000L));
    app->add_option("--starts", starts, "Optimiser starts (default: sizes.optimizer_starts)")
        ->check(CLI::Range(1L, 10000L));
  }
  if (which & kRegion) {
    app->add_option("--region", region,
                    "Region the design covers: joint (the joint 1 % likelihood-ratio contour, "
                    "default) or paper (the paper's "
                    "one-at-a-time box); default: the study's [calibration] region")
        ->check(CLI::IsMember({"joint", "paper"}));
    app->add_option("--interval", interval,
                    "The 95 % interval printed as ci95: profile (the profile-likelihood interval, "
                    "default) or posterior (the "
                    "posterior's central interval); both are in summary.json. Default: the study's "
                    "[calibration] interval")
        ->check(CLI::IsMember({"profile", "posterior"}));
    app->add_option("--design", design,
                    "adaptive (a Latin hypercube, then rounds where the posterior lies) or lhs "
                    "(one Latin hypercube); "
                    "default: the study's [calibration] design (adaptive for joint, lhs for paper)")
        ->check(CLI::IsMember({"adaptive", "lhs"}));
  }
  if (which & kRounds)
    app->add_option("--max-rounds", max_rounds,
                    "Adaptive design rounds after the first Latin hypercube (default: the study's "
                    "[calibration] max_rounds)")
        ->check(CLI::Range(0L, 100L));
  if (which & kSteps)
    app->add_option("--steps", steps,
                    "frozen (one integrator step sequence per stage: a smooth SSE, the accuracy "
                    "chosen from the data) or adaptive "
                    "(each run chooses its steps); default: the study's [calibration] steps")
        ->check(CLI::IsMember({"frozen", "adaptive"}));
  if (which & kRounds)
    app->add_option("--ridge-steps", ridge_steps,
                    "Steps per ridge trace of the joint region, 0: none (default: the study's "
                    "[calibration] ridge_steps)")
        ->check(CLI::Range(0L, 1000L));
}

void CalibrationFlags::addFieldFlags(CommandHandle& handle) {
  handle.field_flags["gibbs_iterations"] = "--iterations";
  handle.field_flags["gibbs_burn_in"] = "--burn-in";
  handle.field_flags["optimizer_starts"] = "--starts";
}

}  // namespace dtwin::cli
