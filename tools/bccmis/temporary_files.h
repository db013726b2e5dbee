// bccmis CLI: the temporary files of the staged outputs (io.h, OutputSet),
// and the directories that hold them, removed when SIGINT, SIGTERM or SIGHUP
// ends the run (spec/cli.md, "What a signal leaves"; spec/distributed.md D18).
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

/// mkdtemp(`name`) (a path ending in XXXXXX, replaced by the name made),
/// with the directory registered for removal on a signal from the moment it
/// exists: false with errno set when it cannot be made. The handler removes
/// a registered directory after unlinking every registered file, when it is
/// empty by then (of the processes sharing one, the last signalled removes it).
bool make_temporary_directory(std::string& name);

/// Registers the directory `path`, made by another process of the run, for
/// removal on a signal as make_temporary_directory() does.
void track_temporary_directory(const std::string& path);

/// Unregisters the directory `path` (removed, or left to another process).
void untrack_temporary_directory(const std::string& path);

}  // namespace bccmis::cli
