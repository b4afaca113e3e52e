#!/bin/sh
# Runs a display test under `xvfb-run -a`, starting the search for a free display at $1.
# Retries (up to three times, each from a display number 3 higher) only when the X server could
# not be reached at all ("Failed to open display"): on a loaded machine Xvfb occasionally is not
# there in time, or another xvfb-run takes the same number. Any other failure is reported as is.
# Usage: xvfb_run.sh XVFB_RUN FIRST_DISPLAY COMMAND [ARGS...]
xvfb_run=$1
display=$2
shift 2
for attempt in 1 2 3; do
    output=$("$xvfb_run" -a -n "$display" "$@" 2>&1)
    status=$?
    case "$output" in
        *"Failed to open display"*)
            if [ "$attempt" -lt 3 ]; then
                echo "xvfb_run.sh: no X server on attempt $attempt (display :$display), retrying" >&2
                display=$((display + 3))
                continue
            fi
            ;;
    esac
    break
done
printf '%s\n' "$output"
exit "$status"
