# Sourced by scripts that build two things at once: a program linked whole (one codegen unit)
# keeps one core busy, so a second build beside it uses the machine's other core. Two cargo
# builds can only run side by side in different build directories (a profile of their own, or
# CARGO_TARGET_DIR): in the same one, the second waits for the first one's lock.

# side LOG COMMAND...: runs COMMAND (a function too) in the background, its output in LOG;
# its process id in $side_pid.
side() {
    local log=$1
    shift
    "$@" >"$log" 2>&1 &
    side_pid=$!
}

# side_wait PID LOG WHAT: waits for the command; if it failed, prints its log and exits.
side_wait() {
    if ! wait "$1"; then
        cat "$2"
        echo "error: $3 failed (its log, above: $2)" >&2
        exit 1
    fi
}
