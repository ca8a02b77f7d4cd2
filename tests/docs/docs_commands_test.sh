#!/usr/bin/env bash
# Runs the command blocks of README.md and docs/*.md, so a documented command line cannot
# drift from the tools. Every ```sh block must carry a marker on the line before its fence:
#
#   <!-- doc-test: run -->            runs offline in seconds: executed here, must exit 0
#   <!-- doc-test: run netns -->      the same inside a private network and PID namespace (DDS
#                                     commands: their traffic and domain meet nobody else's, and
#                                     every process they start dies with the block); needs root,
#                                     skipped with that reason without it
#   <!-- doc-test: skip REASON -->    not run here, with the reason (long, builds, synopsis, ...)
#
# An unmarked ```sh block fails the test, so a new command is either run or its skip stated.
# Blocks run in the order they appear, each with bash -euo pipefail, in a scratch copy of the
# repository (its entries linked, build/ = BUILD_DIR, ../shared = the real one), so what they
# write lands in the scratch folder; one scratch folder per Markdown file.
#
#   docs_commands_test.sh REPO BUILD_DIR
set -euo pipefail
repo="$(cd "${1:?usage: docs_commands_test.sh REPO BUILD_DIR}" && pwd)"
build="$(cd "${2:?usage: docs_commands_test.sh REPO BUILD_DIR}" && pwd)"
shared="$(realpath -m "$repo/../shared")"
block_timeout="${CLOUDSHAPE_DOC_BLOCK_TIMEOUT:-180}"

scratch="$(mktemp -d "${TMPDIR:-/tmp}/cloudshape-doc-commands.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT

# A fresh copy of the repository layout for one Markdown file: links, not copies.
make_workspace() {
  local ws="$scratch/$1" entry
  mkdir -p "$ws/repo"
  for entry in "$repo"/* "$repo"/.ci; do
    [[ "$(basename "$entry")" == build ]] && continue
    ln -s "$entry" "$ws/repo/"
  done
  ln -s "$build" "$ws/repo/build"
  [[ -d "$shared" ]] && ln -s "$shared" "$ws/shared"
  echo "$ws/repo"
}

# Splits a Markdown file into blocks: writes NNN.sh and NNN.mark (the marker text, or
# "unmarked"), and NNN.line (the fence's line number) into a folder.
split_blocks() {
  awk -v out="$2" '
    function flush() { close(out "/" sprintf("%03d", n) ".sh") }
    !in_sh && /^```(sh|bash)[[:space:]]*$/ {
      n++
      mark = "unmarked"
      if (prev ~ /^<!-- doc-test: (run|run netns|skip [^>]+) -->$/) {
        mark = prev
        sub(/^<!-- doc-test: /, "", mark)
        sub(/ -->$/, "", mark)
      }
      print mark > (out "/" sprintf("%03d", n) ".mark"); close(out "/" sprintf("%03d", n) ".mark")
      print NR > (out "/" sprintf("%03d", n) ".line"); close(out "/" sprintf("%03d", n) ".line")
      printf "" > (out "/" sprintf("%03d", n) ".sh")
      in_sh = 1
      next
    }
    in_sh && /^```[[:space:]]*$/ { flush(); in_sh = 0; next }
    in_sh { print >> (out "/" sprintf("%03d", n) ".sh"); next }
    { prev = $0 }
  ' "$1"
}

# Whether this process may make network and PID namespaces (root, unshare and ip present).
netns_ok=0
if unshare --net --pid --fork --mount-proc sh -c 'ip link set lo up' 2>/dev/null; then netns_ok=1; fi

ran=0 skipped=0 failures=0
shopt -s nullglob
for doc in "$repo/README.md" "$repo"/docs/*.md; do
  rel="${doc#"$repo"/}"
  name="$(echo "$rel" | tr '/.' '__')"
  blocks="$scratch/blocks-$name"
  mkdir -p "$blocks"
  split_blocks "$doc" "$blocks"
  ws=""
  for script in "$blocks"/*.sh; do
    base="${script%.sh}"
    mark="$(cat "$base.mark")"
    where="$rel:$(cat "$base.line")"
    case "$mark" in
      unmarked)
        echo "FAIL $where: a command block without <!-- doc-test: run --> or <!-- doc-test: skip REASON -->"
        failures=$((failures + 1))
        continue ;;
      skip*)
        echo "skip $where: ${mark#skip }"
        skipped=$((skipped + 1))
        continue ;;
    esac
    if grep -q '\.\./shared' "$script" && [[ ! -d "$shared" ]]; then
      if [[ "${CI:-}" == true || "${CI:-}" == 1 ]]; then
        echo "FAIL $where: needs $shared (CI=true requires the shared data)"
        failures=$((failures + 1))
      else
        echo "skip $where: $shared is missing (outside CI)"
        skipped=$((skipped + 1))
      fi
      continue
    fi
    runner=(bash -euo pipefail)
    if [[ "$mark" == "run netns" ]]; then
      if ((netns_ok == 0)); then
        echo "skip $where: needs a private network namespace (root, unshare), not available here"
        skipped=$((skipped + 1))
        continue
      fi
      # shellcheck disable=SC2016  # $0 is for the inner shell
      runner=(unshare --net --pid --fork --mount-proc
              bash -c 'ip link set lo up && exec bash -euo pipefail "$0"')
    fi
    [[ -n "$ws" ]] || ws="$(make_workspace "$name")"
    start=$SECONDS
    status=0
    # Service logs and pid files in the scratch folder, never in the shared build/logs: pids from
    # a PID namespace mean other processes outside it, where a later launch.sh stop would look.
    (cd "$ws" && CLOUDSHAPE_LOG_DIR="$ws/../logs" timeout "$block_timeout" "${runner[@]}" "$script") \
      >"$base.out" 2>&1 || status=$?
    if ((status == 0)); then
      echo "ok   $where ($((SECONDS - start)) s): $(grep -m1 -v '^#' "$script")"
      ran=$((ran + 1))
    else
      echo "FAIL $where: exit status $status after $((SECONDS - start)) s; the block:"
      sed 's/^/    /' "$script"
      echo "  its output (last 30 lines):"
      tail -n 30 "$base.out" | sed 's/^/    /'
      failures=$((failures + 1))
    fi
  done
done
# The README also shows command lines inline (its figures table): each must appear in a command
# block of README.md or docs/, where it is run or its skip is stated.
# shellcheck disable=SC2016  # the backticks are Markdown's, not the shell's
inline_commands() { grep -o '`[^`]*`' "$1" | tr -d '`' | grep -E '^(build/bin/|tools/)[^ ]+ ' || true; }
cat "$scratch"/blocks-*/*.sh >"$scratch/all-blocks.txt"
inline=0
while IFS= read -r command; do
  inline=$((inline + 1))
  if ! grep -qF -- "$command" "$scratch/all-blocks.txt"; then
    echo "FAIL README.md: \`$command\` is in no command block of README.md or docs/"
    failures=$((failures + 1))
  fi
done < <(inline_commands "$repo/README.md")
echo "$inline inline command lines of README.md found in command blocks"
echo "$ran blocks ran, $skipped skipped (reasons above), $failures failed"
((ran > 0)) || { echo "FAIL: no block ran: the markers or the test are broken"; exit 1; }
((failures == 0))
