#pragma once
// `twin list` as one call each: what a study holds (its assemblies, scenarios, options,
// calibrated parameters, effects, diagnosis candidates, output channels and parameters), and every
// registry of the twin as the Markdown page docs/registries.md.
#include <string>

#include "common/registry.hpp"

namespace dtwin {

/// The text `twin list --study STUDY` prints; with `parameters`, every parameter of the study with
/// its value, unit and source at the end.
std::string studyListing(const std::string& study_path, bool parameters);

/// Every registry of the twin as Markdown tables (docs/registries.md is this text, checked by a
/// test). The commands are the program's own: `commands` holds each with whether it runs on every
/// MPI rank.
std::string registriesMarkdown(const Registry<bool>& commands);

}  // namespace dtwin
