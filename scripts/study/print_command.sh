#!/usr/bin/env bash
# print_command.sh COMMAND...: prints the command, shell-quoted, instead of running it: the RUN
# prefix of `make study-jobs`, which lists one stage's recipes for GNU parallel or a job array
# (run them from the checkout's top folder, where study.mk's relative paths hold).
printf '%q ' "$@"
printf '\n'
