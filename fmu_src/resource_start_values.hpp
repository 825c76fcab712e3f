// Start values that a copy of an FMU carries in resources/start_values.txt, so that a system
// archive (SSP) can ship configured copies that every importer runs alike, also those that
// neither read the SSP's parameter bindings nor apply the modelDescription's start values
// (fmpy 0.3.32's simulate_ssp). One "name = value" per line; blank lines and lines starting
// with '#' are skipped. contactbody.system writes it, with the copy's modelDescription start
// values edited to match.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace contactbody::fmu {

// The file's path from fmi2Instantiate's fmuResourceLocation (a file URI); "" if there is
// no location or it is not a file URI.
std::string start_values_path(const char* resource_location);
// The resources folder itself, with a trailing '/' ("" as above).
std::string resources_directory(const char* resource_location);

// (name, value) pairs of the file, in order; none if there is no file. Throws
// std::runtime_error naming the line of a malformed one.
std::vector<std::pair<std::string, std::string>> read_start_values(const std::string& path);

}  // namespace contactbody::fmu
