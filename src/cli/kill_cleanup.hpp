// What a kill leaves behind: nothing. SIGINT (Ctrl-C), SIGTERM and SIGHUP remove the temporary
// files of outputs being written, then end the process as the signal would have.
#pragma once

namespace dragon::cli {

// Installs the handlers; a signal ignored when dragon started (nohup, say) stays ignored.
void install_kill_cleanup();

}  // namespace dragon::cli
