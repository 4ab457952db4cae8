# The helper of refit_quadric.sh and refit_variants.sh: run LABEL ENVIRONMENT CLOUD...
# runs refit_quadric.cpp, built as /tmp/refit_quadric, on each cloud with the environment.
set -u
q=/tmp/refit_quadric
run() { # label, environment, clouds...
  local label=$1 environment=$2; shift 2
  echo "== $label: $environment"
  for cloud in "$@"; do env $environment $q $cloud; done
}
