#!/usr/bin/env bash
# The cluster against one machine at equal cores, on a machine of 16 cores or more (about 5 minutes).
#
#   OUT=/some/folder PYTHON=/path/to/venv/bin/python bash benchmarks/device_cluster.sh
#
# Needs an environment with assess installed from this checkout and its cluster and test extras
# (pip install -e ".[cluster,test]": distributed, pyslammer's records). Writes into $OUT:
#   machine.txt                 cores, load, versions
#   bench_distributed_16.txt    10,000 items x 18 records x 2 directions (360,000 cases): 16 numba threads
#                               against a loopback cluster of 16 single-threaded workers, 3 timed runs each
#   bench_distributed_2.txt     1,000 items with 2 threads against 2 workers (how each scales from 2 to 16)
#   bench_batch_cluster.txt     18 buildings (the six sample buildings, three copies each) with their HTML
#                               reports: one machine (--jobs 16) against the 16 workers, same files
#   summary.txt                 the lines to quote
# Each step has its time limit (120 + 50 + 120 s): the whole stays under 5 minutes.
set -u
OUT=${OUT:-benchmarks/device-out}
PY=${PYTHON:-python3}
WORKERS=${WORKERS:-16}
cd "$(dirname "$0")/.." || exit 1
mkdir -p "$OUT"
{
  echo "cores: $(nproc)"; uptime
  "$PY" -c "import assess, numba, numpy, distributed, pyslammer; print('assess', assess.__version__, 'numba', \
numba.__version__, 'numpy', numpy.__version__, 'distributed', distributed.__version__)"
} > "$OUT/machine.txt" 2>&1 || { cat "$OUT/machine.txt"; echo "the environment lacks assess[cluster,test]"; exit 1; }
# the numba cache beside the package is written by the first (local) run; the workers then load it
timeout 120 "$PY" benchmarks/bench_distributed.py --items 10000 --workers "$WORKERS" --repeat 3 \
  > "$OUT/bench_distributed_$WORKERS.txt" 2>&1
timeout 50 "$PY" benchmarks/bench_distributed.py --items 1000 --workers 2 --repeat 3 \
  > "$OUT/bench_distributed_2.txt" 2>&1
timeout 120 "$PY" benchmarks/bench_batch_cluster.py --workers "$WORKERS" --copies 3 --format html,xlsx \
  > "$OUT/bench_batch_cluster.txt" 2>&1
uptime >> "$OUT/machine.txt"
grep -hE "^(load|this machine|Dask|throughput|work per|identical|files|cluster)" "$OUT"/bench_*.txt \
  > "$OUT/summary.txt"
cat "$OUT/summary.txt"
