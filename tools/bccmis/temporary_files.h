// bccmis CLI: the temporary files of the staged outputs (io.h, OutputSet),
// removed when SIGINT, SIGTERM or SIGHUP ends the run (spec/cli.md, "What a
// signal leaves").
#pragma once

#include <string>

namespace bccmis::cli {

/// mkstemp(`name`) (a path ending in XXXXXX, replaced by the name made),
/// with the file registered for removal on a signal from the moment it
/// exists: the descriptor, or -1 with errno set. The first call installs
/// the handler for SIGINT, SIGTERM and SIGHUP (a signal that is ignored
/// stays ignored); the handler unlinks every registered path with async-
/// signal-safe calls, restores the default action and raises the signal
/// again, so the run ends as the signal says.
int make_temporary(std::string& name);

/// Unregisters `path` (renamed over its target, or removed).
void untrack_temporary(const std::string& path);

}  // namespace bccmis::cli
