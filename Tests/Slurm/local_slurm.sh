# A one-node Slurm on this machine, in a folder of its own: munged,
# slurmctld and slurmd with their keys, state, spool, logs and sockets under
# $SLURM_DIR, on ports no default installation uses. Sourced by the tests
# (sweep_on_slurm.sh); needs root and the Debian packages slurmctld, slurmd,
# slurm-client and munge (Demos/scripts/install-deps.sh). No systemd, no
# cgroups: processes are tracked by parentage (proctrack/linuxproc).
#
#   slurm_start DIR CPUS   starts the three daemons, waits for the node to be idle;
#                          exports SLURM_CONF so that sbatch, squeue, scancel find them
#   slurm_stop             stops them (by the process ids they wrote)
#   slurm_fail MESSAGE     prints the message and the daemons' logs, stops them, exits 1

slurm_fail() {
  echo "slurm test: FAILED: $*" >&2
  for log in "$SLURM_DIR"/munged.log "$SLURM_DIR"/slurmctld.log "$SLURM_DIR"/slurmd.log; do
    [ -f "$log" ] && { echo "---- last lines of $log" >&2; tail -n 25 "$log" >&2; }
  done
  slurm_stop
  exit 1
}

# Stops whatever of ours is running: each daemon by the id in its pid file.
slurm_stop() {
  for name in slurmd slurmctld munged; do
    pidfile="$SLURM_DIR/$name.pid"
    [ -f "$pidfile" ] || continue
    pid=$(cat "$pidfile" 2>/dev/null)
    [ -n "$pid" ] && kill "$pid" 2>/dev/null
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
    rm -f "$pidfile"
  done
}

slurm_start() {
  SLURM_DIR=$1
  cpus=$2
  [ "$(id -u)" -eq 0 ] || slurm_fail "slurmd must run as root here (it starts jobs as their user); run the test as root"
  for tool in munged mungekey slurmctld slurmd sbatch squeue scancel sinfo; do
    command -v "$tool" >/dev/null || slurm_fail "'$tool' is not installed (Demos/scripts/install-deps.sh installs munge, slurmctld, slurmd, slurm-client)"
  done
  mkdir -p "$SLURM_DIR/state" "$SLURM_DIR/spool" "$SLURM_DIR/munge"
  chmod 700 "$SLURM_DIR/munge"
  # munged insists on a key only its user can read, in folders nobody else can write.
  mungekey --create --keyfile="$SLURM_DIR/munge/munge.key" --force >/dev/null 2>&1 ||
    dd if=/dev/urandom of="$SLURM_DIR/munge/munge.key" bs=1024 count=1 2>/dev/null
  chmod 600 "$SLURM_DIR/munge/munge.key"
  munged --force --socket="$SLURM_DIR/munge/munge.sock" --key-file="$SLURM_DIR/munge/munge.key" \
    --pid-file="$SLURM_DIR/munged.pid" --log-file="$SLURM_DIR/munged.log" --seed-file="$SLURM_DIR/munge/seed" ||
    slurm_fail "munged did not start"

  # Ports from this shell's id, away from Slurm's 6817/6818 and from each other.
  port=$((20000 + ($$ % 20000) * 2))
  host=$(hostname -s)
  memory_mb=$(awk '/MemTotal/ { print int($2 / 1024 / 2) }' /proc/meminfo)
  cat > "$SLURM_DIR/slurm.conf" <<EOF
ClusterName=soaktest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$SLURM_DIR/munge/munge.sock
CredType=cred/munge
StateSaveLocation=$SLURM_DIR/state
SlurmdSpoolDir=$SLURM_DIR/spool
SlurmctldPidFile=$SLURM_DIR/slurmctld.pid
SlurmdPidFile=$SLURM_DIR/slurmd.pid
SlurmctldLogFile=$SLURM_DIR/slurmctld.log
SlurmdLogFile=$SLURM_DIR/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU_Memory
ReturnToService=2
KillWait=30
MinJobAge=600
SchedulerParameters=sched_interval=1
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory_mb State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
  export SLURM_CONF="$SLURM_DIR/slurm.conf"
  slurmctld -i -f "$SLURM_CONF" || slurm_fail "slurmctld did not start"
  slurmd -f "$SLURM_CONF" || slurm_fail "slurmd did not start"
  for _ in $(seq 60); do
    state=$(sinfo -h -N -o %T 2>/dev/null | head -n 1)
    [ "$state" = idle ] && return 0
    sleep 0.5
  done
  slurm_fail "the node did not come up idle within 30 s (sinfo says '${state:-nothing}')"
}
