#!/usr/bin/env bash
# CalculiX peer for bench/shell_solve: write decks with write_inp.py, run ccx on each,
# time it, and print one row per mesh (plus a CSV for the side-by-side comparison).
#
# Usage:
#   bench/calculix/run_peer.sh [options] MESH...
#     MESH            N | MODEL:N | MODEL:N:ELEMENT   (MODEL scordelis|plate|plate_soft,
#                     ELEMENT S4|S8R|S4R; plain N uses --model and --element)
#   --model M         default model for plain N (default scordelis)
#   --element E       default element for plain N (default S4)
#   --threads T       OMP_NUM_THREADS for ccx (default: $OMP_NUM_THREADS, else 2)
#   --csv FILE        also write the CSV to FILE; "-" puts the CSV on stdout and the
#                     human-readable table on stderr
#   --keep DIR        keep decks, logs and .dat files in DIR (default: a temp dir,
#                     removed at exit)
#   --timeout S       give up on one ccx run after S seconds (default 600)
#
# Examples:
#   bench/calculix/run_peer.sh 8 16 32 64 128
#   bench/calculix/run_peer.sh --csv peer.csv scordelis:16 scordelis:8:S8R plate:200
#
# CSV columns (header line included):
#   model,element,n,elements,nodes,shell_dof,equations,displacement,reference,
#   rel_error,wall_s,peak_mib,threads
# displacement is the magnitude of the monitored displacement (u_z at the middle of the
# roof's free edge, u_z at the plate centre); rel_error = displacement/reference - 1;
# shell_dof = 6 * nodes (the unconstrained count of a 6-DOF-per-node shell model, for
# comparing with our MITC4); equations = ccx's own count after expanding S4 into C3D8I
# bricks (S8R into C3D20R) and applying constraints.  Missing values are "NA".
#
# This is a benchmark, not a test: it installs calculix-ccx (and GNU time for the
# peak-memory figure) with apt-get when they are missing.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
model=scordelis
element=S4
threads=${OMP_NUM_THREADS:-2}
csv=""
keep=""
timeout_s=600
meshes=()

die() { echo "run_peer.sh: $*" >&2; exit 2; }

while [[ $# -gt 0 ]]; do
    case $1 in
        --model) model=${2:?}; shift 2 ;;
        --element) element=${2:?}; shift 2 ;;
        --threads) threads=${2:?}; shift 2 ;;
        --csv) csv=${2:?}; shift 2 ;;
        --keep) keep=${2:?}; shift 2 ;;
        --timeout) timeout_s=${2:?}; shift 2 ;;
        -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
        -*) die "unknown option $1" ;;
        *) meshes+=("$1"); shift ;;
    esac
done
[[ ${#meshes[@]} -gt 0 ]] || die "no mesh given (try: run_peer.sh 8 16 32)"
[[ $threads =~ ^[1-9][0-9]*$ ]] || die "--threads wants a positive integer, got '$threads'"

# --- tools -------------------------------------------------------------------------
as_root() { if [[ $(id -u) -eq 0 ]]; then "$@"; else sudo "$@"; fi; }
apt_install() {
    # A bare container may never have fetched the package lists.
    as_root apt-get install -y "$@" >&2 ||
        { as_root apt-get update >&2 && as_root apt-get install -y "$@" >&2; }
}
command -v ccx >/dev/null || apt_install calculix-ccx
[[ -x /usr/bin/time ]] || apt_install time || true
command -v python3 >/dev/null || die "python3 is needed for write_inp.py"

# --- work directory ----------------------------------------------------------------
if [[ -n $keep ]]; then
    mkdir -p "$keep"
    work=$(cd "$keep" && pwd)
else
    work=$(mktemp -d "${TMPDIR:-/tmp}/ccx_peer.XXXXXX")
    trap 'rm -rf "$work"' EXIT
fi

# Human table goes to stdout, unless the CSV claims stdout.
if [[ $csv == "-" ]]; then exec 3>&2; else exec 3>&1; fi
csv_header="model,element,n,elements,nodes,shell_dof,equations,displacement,reference,"
csv_header+="rel_error,wall_s,peak_mib,threads"
csv_rows=()

printf '%-13s %-4s %5s %8s %10s %10s %13s %13s %9s %9s %9s\n' \
    model elem N elements shell_dof equations displacement reference rel_err wall_s peak_MiB >&3

failed=0
for spec in "${meshes[@]}"; do
    IFS=: read -r m n e <<<"$spec"
    if [[ -z ${n:-} ]]; then n=$m; m=$model; fi
    e=${e:-$element}
    [[ $n =~ ^[1-9][0-9]*$ ]] || die "bad mesh '$spec'"
    job="${m}_${e}_${n}"

    meta=$(python3 "$here/write_inp.py" "$m" "$n" --element "$e" -o "$work/$job.inp")
    # meta: model=... element=... n=... elements=... nodes=... monitor_node=... ...
    declare -A kv=()
    for pair in $meta; do kv[${pair%%=*}]=${pair#*=}; done

    # Time ccx alone (deck writing excluded).  Both variables: ccx reads
    # OMP_NUM_THREADS; CCX_NPROC_EQUATION_SOLVER would otherwise let SPOOLES pick.
    start=$(date +%s.%N)
    rc=0
    if [[ -x /usr/bin/time ]]; then
        ( cd "$work" && OMP_NUM_THREADS=$threads CCX_NPROC_EQUATION_SOLVER=$threads \
            timeout "$timeout_s" /usr/bin/time -v -o "$job.time" ccx -i "$job" \
            >"$job.log" 2>&1 ) || rc=$?
    else
        ( cd "$work" && OMP_NUM_THREADS=$threads CCX_NPROC_EQUATION_SOLVER=$threads \
            timeout "$timeout_s" ccx -i "$job" >"$job.log" 2>&1 ) || rc=$?
    fi
    end=$(date +%s.%N)
    wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')

    peak=NA
    if [[ -f $work/$job.time ]]; then
        peak=$(awk -F: '/Maximum resident set size/ { printf "%.0f", $2 / 1024 }' \
            "$work/$job.time")
        [[ -n $peak ]] || peak=NA
    fi
    # ccx prints "number of equations" and the count on the next line.
    equations=$(awk 'f { print $1; exit } /number of equations/ { f = 1 }' \
        "$work/$job.log" 2>/dev/null || true)
    equations=${equations:-NA}
    # .dat: "displacements (vx,vy,vz) for set MON ..." then "node ux uy uz".
    disp=NA
    if [[ $rc -eq 0 && -f $work/$job.dat ]]; then
        disp=$(awk -v node="${kv[monitor_node]}" -v dof="${kv[monitor_dof]}" '
            /displacements/ { f = 1; next }
            f && $1 == node { v = $(1 + dof); if (v < 0) v = -v; printf "%.7g\n", v; exit }' \
            "$work/$job.dat")
        disp=${disp:-NA}
    fi
    ref=${kv[reference]}
    if [[ $disp == NA ]]; then
        err=NA
        failed=1
        echo "run_peer.sh: $job failed (rc $rc); see $work/$job.log" >&2
    else
        err=$(awk -v d="$disp" -v r="$ref" 'BEGIN { printf "%.4e", d / r - 1 }')
    fi
    shell_dof=$((6 * kv[nodes]))

    printf '%-13s %-4s %5s %8s %10s %10s %13s %13.6g %9s %9s %9s\n' \
        "${kv[model]}" "$e" "$n" "${kv[elements]}" "$shell_dof" "$equations" "$disp" \
        "$ref" "$err" "$wall" "$peak" >&3
    row="${kv[model]},$e,$n,${kv[elements]},${kv[nodes]},$shell_dof,$equations,$disp,$ref"
    csv_rows+=("$row,$err,$wall,$peak,$threads")
    unset kv
done

if [[ -n $csv ]]; then
    if [[ $csv == "-" ]]; then
        printf '%s\n' "$csv_header" "${csv_rows[@]}"
    else
        printf '%s\n' "$csv_header" "${csv_rows[@]}" >"$csv"
    fi
fi
exit "$failed"
