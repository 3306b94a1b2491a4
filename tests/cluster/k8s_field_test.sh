#!/usr/bin/env bash
# The Kubernetes examples without a cluster: examples/cluster/field-job.yaml must be an
# Indexed Job whose pods and field-merge-job.yaml's pod share one volume, and the shell they
# run must do the field: each index's command is run here with JOB_COMPLETION_INDEX set, as
# the pods would be, then the merge's, and the outputs and merged summary are checked.
#   tests/cluster/k8s_field_test.sh CALIPER3D SOURCE_DIR     (about 5 s)
set -euo pipefail
caliper3d=$(realpath "${1:?usage: k8s_field_test.sh CALIPER3D SOURCE_DIR}")
src=$(realpath "${2:?usage: k8s_field_test.sh CALIPER3D SOURCE_DIR}")
wells=10
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
work=$(mktemp -d /tmp/caliper3d-k8s-field.XXXXXX)
trap 'rm -rf "$work"' EXIT

# The structure a cluster relies on, and each container's script into a file. Debian's
# python3 and python3-yaml (scripts/install-deps.sh), whatever python3 comes first on PATH.
/usr/bin/python3 - "$src/examples/cluster" "$work" <<'PY' || fail "the Job manifests (above)"
import sys, yaml
folder, work = sys.argv[1], sys.argv[2]
field = yaml.safe_load(open(f"{folder}/field-job.yaml"))
merge = yaml.safe_load(open(f"{folder}/field-merge-job.yaml"))
for doc in (field, merge):
    assert doc["apiVersion"] == "batch/v1" and doc["kind"] == "Job", doc["kind"]
assert field["spec"]["completionMode"] == "Indexed"
assert field["spec"]["completions"] >= field["spec"]["parallelism"] >= 1
pods = [doc["spec"]["template"]["spec"] for doc in (field, merge)]
for name, pod in zip(("field", "merge"), pods):
    assert pod["restartPolicy"] == "Never"
    (c,) = pod["containers"]
    assert c["command"] == ["/bin/bash", "-c"], c["command"]
    assert c["workingDir"] == "/field/run"
    assert c["volumeMounts"][0]["mountPath"] == "/field"
    env = {e["name"]: e["value"] for e in c.get("env", [])}
    with open(f"{work}/{name}.sh", "w") as out:
        out.write(c["args"][0])
    with open(f"{work}/{name}.env", "w") as out:
        out.write("\n".join(f"{k}={v}" for k, v in env.items()) + "\n")
assert pods[0]["volumes"] == pods[1]["volumes"], "the two Jobs mount different volumes"
rules = field["spec"]["podFailurePolicy"]["rules"]
assert rules[0]["onExitCodes"]["containerName"] == pods[0]["containers"][0]["name"]
PY
grep -q '^MANIFEST=/field/manifest.csv$' "$work/field.env" || fail "the field Job's MANIFEST: $(cat "$work/field.env")"

# /field is the test's folder; caliper3d is on the PATH, as in the image.
"$caliper3d" synth --field "$wells" --length 30 --step 0.05 -o "$work/field/" >/dev/null
mkdir -p "$work/bin" "$work/field/run"
ln -s "$caliper3d" "$work/bin/caliper3d"
export PATH="$work/bin:$PATH" MANIFEST="$work/field/manifest.csv"
runPods() { # ROWS_PER_TASK
  local per_task=$1 i
  rm -rf "$work/field/run" && mkdir -p "$work/field/run"
  for ((i = 0; i < (wells + per_task - 1) / per_task; i++)); do
    (cd "$work/field/run" && JOB_COMPLETION_INDEX=$i ROWS_PER_TASK=$per_task \
      bash "$work/field.sh" >/dev/null) || fail "index $i with ROWS_PER_TASK=$per_task failed"
  done
  (cd "$work/field/run" && FIELD_ROWS=$wells bash "$work/merge.sh") ||
    fail "the merge pod failed (ROWS_PER_TASK=$per_task)"
  [ "$(wc -l <"$work/field/run/field-summary.jsonl")" -eq "$wells" ] || fail "merged summary lines"
  local row
  for ((row = 0; row < wells; row++)); do
    [ -s "$work/field/run/out/$(printf 'well-%03d' "$row").csv" ] || fail "no report of row $row"
    sed -n "$((row + 1))p" "$work/field/run/field-summary.jsonl" | grep -q "^{\"row\":$row,.*\"status\":\"ok\"" ||
      fail "merged line $((row + 1)) is not row $row, ok"
  done
}
runPods 1
runPods 4
echo "PASS: the indexed Job's and the merge Job's commands over $wells wells, one a pod and 4 a pod"
