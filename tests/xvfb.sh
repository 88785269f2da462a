# Sourced by the kiosk tests: start_xvfb N starts an Xvfb on the first display number
# from N to N+8 that is free, starts and answers.
# Sets started_display (":N") and started_pid, both empty when none could be started.
start_xvfb() {
  started_display=
  started_pid=
  for n in $(seq "$1" $(($1 + 8))); do
    [ -e "/tmp/.X$n-lock" ] && continue
    # -noreset: by default the server resets when its last client (the probe below) leaves,
    # and a client connecting during that reset is refused
    Xvfb ":$n" -screen 0 1024x768x24 -nolisten tcp -noreset >/dev/null 2>&1 &
    started_pid=$!
    for i in $(seq 1 100); do
      kill -0 "$started_pid" 2>/dev/null || break # it could not take the display
      if DISPLAY=":$n" xdotool getdisplaygeometry >/dev/null 2>&1; then
        sleep 0.2
        kill -0 "$started_pid" 2>/dev/null && started_display=":$n" # still ours, not another's dying server
        break
      fi
      sleep 0.1
    done
    [ -n "$started_display" ] && return
    kill "$started_pid" 2>/dev/null
    started_pid=
  done
}
