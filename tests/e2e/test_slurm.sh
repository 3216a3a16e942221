#!/usr/bin/env bash
# scripts/slurm/ on a real Slurm cluster: the test brings up munged, slurmctld and slurmd from
# Debian's packages on this machine (its own key, socket, ports, state and spool folders: it
# touches nothing of a cluster that may run here), submits a batch of bundled parts through
# sbatch, waits for the summary job and checks that its summary.csv is the one samples/Makefile
# writes for the same parts and parameters. The daemons are stopped however the test ends.
# Where they cannot start (not root, not installed, refused), it says why and exits 77: skipped.
. "$(dirname "$0")/lib.sh" || exit 1

skip() {
  echo "SKIP: $*"
  exit 77
}

cluster=$WORK/cluster
daemon_pids=()
stop_cluster() {
  if [ ${#daemon_pids[@]} -gt 0 ]; then
    # Jobs still running are cancelled through this test's own controller (if it started),
    # and their slurmstepd given time to report and leave before the daemons stop.
    if [ -s "$cluster/slurmctld.pid" ]; then
      export SLURM_CONF=$cluster/slurm.conf
      scancel --quiet --user="$(id -un)" 2>/dev/null
      for _ in $(seq 100); do
        [ -n "$(squeue --noheader 2>/dev/null)" ] || break
        sleep 0.2
      done
    fi
    local pid
    for pid in "${daemon_pids[@]}"; do kill "$pid" 2>/dev/null; done
    for _ in $(seq 50); do
      local alive=0
      for pid in "${daemon_pids[@]}"; do kill -0 "$pid" 2>/dev/null && alive=1; done
      [ $alive -eq 1 ] || break
      sleep 0.2
    done
    for pid in "${daemon_pids[@]}"; do kill -KILL "$pid" 2>/dev/null; done
  fi
  rm -rf "$WORK"
}
trap stop_cluster EXIT

# A daemon's pid from its pid file, once it has written one (within 10 s).
remember_pid() {
  for _ in $(seq 50); do
    if [ -s "$1" ]; then
      daemon_pids+=("$(cat "$1")")
      return 0
    fi
    sleep 0.2
  done
  return 1
}

# A TCP port nothing listens on, at random in 20000-59999.
free_port() {
  local port
  for _ in $(seq 100); do
    port=$((20000 + RANDOM % 40000))
    if ! (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null; then
      echo "$port"
      return
    fi
  done
  return 1
}

[ "$(id -u)" -eq 0 ] || skip "slurmd must run as root to start jobs, and this test runs as $(id -un)"
for tool in munged slurmctld slurmd sbatch scontrol sinfo scancel; do
  command -v "$tool" >/dev/null || skip "$tool is not installed (scripts/setup.sh installs slurm-wlm and munge)"
done

# munged insists that every folder above its socket is searchable by all.
chmod 755 "$WORK"
mkdir -m 755 "$cluster"
mkdir "$cluster/state" "$cluster/spool"
head -c 1024 /dev/urandom >"$cluster/munge.key"
chmod 400 "$cluster/munge.key"
munged --socket="$cluster/munge.socket" --key-file="$cluster/munge.key" \
  --pid-file="$cluster/munged.pid" --log-file="$cluster/munged.log" \
  --seed-file="$cluster/munged.seed" 2>"$cluster/munged.err" ||
  skip "munged does not start: $(tail -n 1 "$cluster/munged.err")"
remember_pid "$cluster/munged.pid" || skip "munged wrote no pid file"

node=$(hostname -s)
controller_port=$(free_port) || skip "no free TCP port found"
node_port=$controller_port
while [ "$node_port" = "$controller_port" ]; do
  node_port=$(free_port) || skip "no free TCP port found"
done
touch "$cluster/plugstack.conf"
cat >"$cluster/slurm.conf" <<EOF
ClusterName=ncverify-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$controller_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$cluster/munge.socket
StateSaveLocation=$cluster/state
SlurmdSpoolDir=$cluster/spool
SlurmctldPidFile=$cluster/slurmctld.pid
SlurmdPidFile=$cluster/slurmd.pid
SlurmctldLogFile=$cluster/slurmctld.log
SlurmdLogFile=$cluster/slurmd.log
PlugStackConfig=$cluster/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
# Arrays of at most 3 tasks, so that submit.sh has to split the 5 parts in two arrays.
MaxArraySize=3
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=ncverify Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
for variable in $(env | grep -o '^SLURM_[A-Z_]*'); do unset "$variable"; done
export SLURM_CONF=$cluster/slurm.conf

slurmctld -f "$SLURM_CONF" 2>"$cluster/slurmctld.err" ||
  skip "slurmctld does not start: $(tail -n 1 "$cluster/slurmctld.err")"
remember_pid "$cluster/slurmctld.pid" ||
  skip "slurmctld stopped at once: $(tail -n 1 "$cluster/slurmctld.log" 2>/dev/null)"
slurmd -f "$SLURM_CONF" -N "$node" 2>"$cluster/slurmd.err" ||
  skip "slurmd does not start: $(tail -n 1 "$cluster/slurmd.err")"
remember_pid "$cluster/slurmd.pid" ||
  skip "slurmd stopped at once: $(tail -n 1 "$cluster/slurmd.log" 2>/dev/null)"
for _ in $(seq 150); do
  [ "$(sinfo --noheader --format=%t 2>/dev/null)" = idle ] && break
  sleep 0.2
done
[ "$(sinfo --noheader --format=%t 2>/dev/null)" = idle ] ||
  skip "the node did not come up: $(grep -h error "$cluster/slurmd.log" "$cluster/slurmctld.log" | tail -n 1)"

# The parts: box workpieces that pass and fail at this tolerance, a workpiece without its
# nominal, and a family whose nominal cannot be read (its grid task fails).
parts=$WORK/parts
mkdir "$parts"
cp "$NCV_SOURCE_DIR"/samples/parts/box_{nominal,offset,top_raised,top_lowered,scallop}.stl "$parts/"
cp "$parts/box_offset.stl" "$parts/widget_a.stl"
cp "$parts/box_offset.stl" "$parts/broken_a.stl"
head -c 200 "$parts/box_nominal.stl" >"$parts/broken_nominal.stl"
settings=(NCVERIFY="$NCVERIFY" STEP=3% TOL=0.15)

make -f "$NCV_SOURCE_DIR/samples/Makefile" PARTS="$parts" OUT="$WORK/make" "${settings[@]}" \
  -j2 -k >"$WORK/make.log" 2>&1
check "the Makefile's batch fails (parts out of tolerance)" test $? -ne 0
check "the Makefile wrote its summary" test -s "$WORK/make/summary.csv"

"$NCV_SOURCE_DIR/scripts/slurm/submit.sh" "$parts" "$WORK/refused" "${settings[@]}" \
  -- --partition=no-such-partition >"$WORK/refused.log" 2>&1
check "submit.sh fails when sbatch refuses" test $? -ne 0
check "and says why" grep -q 'no-such-partition\|invalid partition' "$WORK/refused.log"

started=$SECONDS
"$NCV_SOURCE_DIR/scripts/slurm/submit.sh" "$parts" "$WORK/slurm" "${settings[@]}" \
  >"$WORK/submit.log" 2>&1
check "submit.sh submits the batch" test $? -eq 0
# final_state JOB: waits (at most 5 minutes) for the job to end and prints its state.
final_state() {
  local state=
  for _ in $(seq 600); do
    state=$(scontrol show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2)
    case $state in PENDING | RUNNING | CONFIGURING | COMPLETING | "") sleep 0.5 ;; *) break ;; esac
  done
  echo "$state"
}
state=$(final_state "$(tail -n 1 "$WORK/submit.log")")
echo "slurm batch: $((SECONDS - started)) s from sbatch to the summary job's end ($state)"
check "the summary job ran, and failed as parts are out of tolerance" test "$state" = FAILED
check "Slurm's summary is the Makefile's, byte for byte" \
  cmp "$WORK/make/summary.csv" "$WORK/slurm/summary.csv"
check "one grid task per nominal" \
  test "$(ls "$WORK"/slurm/batch/log/ncverify-grid-*.out | wc -l)" -eq 2
check "the parts in two arrays of at most MaxArraySize tasks" \
  grep -q '^parts: [0-9]*:[0-9]*$' "$WORK/submit.log"
check "one part task per workpiece with a nominal" \
  test "$(ls "$WORK"/slurm/batch/log/ncverify-part-*.out | wc -l)" -eq 5
check "the parts out of tolerance fail" \
  test "$(grep -c ',fail,$' "$WORK/slurm/summary.csv")" -eq 3
# box_scallop's scallops are within the zone, proven so between the samples too.
check "the part within it passes" grep -q '^"box_scallop",.*,pass,$' "$WORK/slurm/summary.csv"
check "a part without a nominal is an error row" \
  grep -q '^"widget_a",.*,error,"no nominal: ' "$WORK/slurm/summary.csv"
check "a part whose grid task failed is an error row quoting it" \
  grep -q '^"broken_a",.*,error,"grid-build: error: .*broken_nominal.stl' "$WORK/slurm/summary.csv"
check "the part task of a failed grid does not rebuild it" \
  grep -q 'broken_nominal.grid is not up to date' "$WORK"/slurm/batch/log/ncverify-part-*.out

# The same batch with every part in two shards: a shard task per shard (both directions),
# the reverse grids with the nominals', and the summary still the Makefile's, byte for byte.
"$NCV_SOURCE_DIR/scripts/slurm/submit.sh" "$parts" "$WORK/sharded" "${settings[@]}" SHARDS=2 \
  >"$WORK/sharded.log" 2>&1
check "submit.sh submits the sharded batch" test $? -eq 0
state=$(final_state "$(tail -n 1 "$WORK/sharded.log")")
check "the sharded batch's summary job ran and failed" test "$state" = FAILED
check "the sharded summary is the Makefile's, byte for byte but for the certified bounds" \
  same_but_bounds "$WORK/make/summary.csv" "$WORK/sharded/summary.csv"
check "one shard task per shard of each workpiece with a nominal" \
  test "$(ls "$WORK"/sharded/batch/log/ncverify-shard-*.out | wc -l)" -eq 10
check "a grid task per nominal and per workpiece (its reverse grid)" \
  test "$(ls "$WORK"/sharded/batch/log/ncverify-grid-*.out | wc -l)" -eq 7
finish
