# Sourced by the campaign's recipe scripts. forward_signals COMMAND...: runs COMMAND and hands it
# the SIGTERM or SIGINT that make passes on to its recipes (a script waiting for a command would
# otherwise die and leave the command running), then waits for it: the programs remove their
# partial outputs and exit 143 or 130. Returns COMMAND's status.
forward_signals() {
  "$@" &
  local child=$! status
  trap "kill -TERM $child 2>/dev/null" TERM
  trap "kill -INT $child 2>/dev/null" INT
  wait $child
  status=$?
  while kill -0 $child 2>/dev/null; do wait $child; status=$?; done
  trap - TERM INT
  return $status
}
