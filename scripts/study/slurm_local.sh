#!/usr/bin/env bash
# slurm_local.sh start|stop DIR: a single-node Slurm on this machine for make test-slurm: munged
# (as the munge user), slurmctld and slurmd as root with a configuration, state and logs of their
# own in DIR (one partition holding this host's cores, ports 16817-16818, no accounting). `start`
# waits until the node is idle (seconds) and prints `export SLURM_CONF=DIR/slurm.conf`; `stop`
# ends the daemons it started. Needs slurmctld, slurmd, slurm-client and munge (make deps).
set -euo pipefail
action=${1:?start|stop} dir=${2:?DIR}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
conf="$dir/slurm.conf"
stop() {  # and wait until they are gone (slurmctld saves its state on the way out)
  local d pid
  for d in slurmd slurmctld; do
    [ -f "$dir/$d.pid" ] || continue
    pid=$(cat "$dir/$d.pid")
    kill "$pid" 2>/dev/null || true
    for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    rm -f "$dir/$d.pid"
  done
}
if [ "$action" = stop ]; then stop; exit 0; fi
for cmd in slurmctld slurmd srun munged; do
  command -v "$cmd" >/dev/null || { echo "slurm_local: $cmd is missing: apt-get install slurmd slurmctld slurm-client munge (make deps)" >&2; exit 2; }
done
[ "$(id -u)" -eq 0 ] || { echo "slurm_local: start the daemons as root" >&2; exit 2; }
host=$(hostname)
mkdir -p "$dir/state" "$dir/spool"
cat >"$conf" <<CONF
ClusterName=cmp
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
# munge: one daemon serves every Slurm on the machine; start it when none answers
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
  mkdir -p /run/munge /var/log/munge /var/lib/munge
  [ -f /etc/munge/munge.key ] || /usr/sbin/mungekey --create >/dev/null 2>&1 || true
  chown -R munge:munge /run/munge /var/log/munge /var/lib/munge /etc/munge
  runuser -u munge -- munged
  for _ in $(seq 50); do munge -n 2>/dev/null | unmunge >/dev/null 2>&1 && break; sleep 0.1; done
fi
stop
export SLURM_CONF="$conf"
slurmctld
slurmd
for _ in $(seq 100); do
  sinfo -h -o %T 2>/dev/null | grep >/dev/null -x idle && { echo "export SLURM_CONF=$conf"; exit 0; }
  sleep 0.1
done
echo "slurm_local: the node did not come up in 10 s (logs: $dir/slurmctld.log, $dir/slurmd.log)" >&2
stop
exit 1
