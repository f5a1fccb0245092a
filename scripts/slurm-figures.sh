#!/bin/bash
# granmix on a Slurm cluster: `make figures` (paper fidelity) over MPI ranks, surviving time limits.
# Submit from the repository root after `make build`:   sbatch scripts/slurm-figures.sh
# One rank per socket, one thread per core of it; all DSMC replicas of all scenes are one pool of
# units handed out longest first (docs/user-guide.md, "Cluster scale"). Five minutes before the time limit Slurm
# sends USR1 to this script, which requeues the job; the ranks then get SIGTERM, write a last
# checkpoint and stop; the requeued job resumes from the checkpoints (bit-identical results).
#SBATCH --job-name=granmix-figures
#SBATCH --nodes=2
#SBATCH --ntasks-per-node=2          # one rank per socket
#SBATCH --cpus-per-task=16           # threads per rank: the cores of one socket
#SBATCH --time=01:00:00
#SBATCH --signal=B:USR1@300          # to this script, 5 min before the limit
#SBATCH --requeue
#SBATCH --open-mode=append           # a requeued job appends to the same log
#SBATCH --output=granmix-figures-%j.log
set -uo pipefail

checkpoints=${GRANMIX_CHECKPOINTS:-$PWD/checkpoints/figures}
out=${GRANMIX_OUT:-out/paper}
mkdir -p "$checkpoints"
if [ -n "$(ls -A "$checkpoints")" ]; then
  resume=(--restart "$checkpoints")        # a requeued run: finished replicas are kept, the rest resume
else
  resume=(--checkpoint "$checkpoints")
fi

trap 'echo "granmix: time limit near, requeueing job $SLURM_JOB_ID"; scontrol requeue "$SLURM_JOB_ID"' USR1

export OMP_NUM_THREADS=$SLURM_CPUS_PER_TASK
srun --cpu-bind=sockets build/granmix validate --fidelity paper --out "$out" \
  --threads "$SLURM_CPUS_PER_TASK" --checkpoint-every 600 "${resume[@]}" &
wait $!     # returns early when USR1 arrives; wait again for srun to finish its clean stop
rc=$?
wait || true
# 0: all pass, 1: a comparison failed (see $out/summary.tsv), 2: bad input, 3: a solver failed.
if [ "$rc" -le 1 ]; then rm -rf "$checkpoints"; fi
exit "$rc"
