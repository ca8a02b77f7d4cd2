#!/usr/bin/env bash
# Every relative link of README.md and docs/*.md must resolve inside the repository: the file
# (or folder) exists, and a #fragment names a heading of the Markdown file it points to
# (GitHub's anchors). Links to the web are not fetched (the CI is offline). Links inside code
# (fenced blocks, `spans`) are not links.
#
#   docs_links_test.sh REPO
set -euo pipefail
repo="$(cd "${1:?usage: docs_links_test.sh REPO}" && pwd)"

# The GitHub anchors of a Markdown file's headings, one per line.
anchors() {
  awk '/^```/ { code = !code; next } !code && /^#+ / { sub(/^#+ +/, ""); print }' "$1" |
    tr '[:upper:]' '[:lower:]' | sed -e 's/[^a-z0-9 _-]//g' -e 's/ /-/g'
}

# The link targets of a Markdown file, one "LINE TARGET" per line.
links() {
  awk '/^```/ { code = !code; next }
       !code {
         line = $0
         gsub(/`[^`]*`/, "", line)
         while (match(line, /\]\([^) ]+\)/)) {
           print NR " " substr(line, RSTART + 2, RLENGTH - 3)
           line = substr(line, RSTART + RLENGTH)
         }
       }' "$1"
}

failures=0
checked=0
shopt -s nullglob
for doc in "$repo/README.md" "$repo"/docs/*.md; do
  rel_doc="${doc#"$repo"/}"
  while read -r line target; do
    case "$target" in
      http://* | https://* | mailto:*) continue ;;
    esac
    checked=$((checked + 1))
    path="${target%%#*}"
    fragment=""
    [[ "$target" == *"#"* ]] && fragment="${target#*#}"
    if [[ -z "$path" ]]; then
      file="$doc"
    else
      file="$(realpath -m "$(dirname "$doc")/$path")"
    fi
    if [[ "$file" != "$repo" && "$file" != "$repo"/* ]]; then
      echo "$rel_doc:$line: $target leaves the repository (name such files in text, not as links)"
      failures=$((failures + 1))
    elif [[ ! -e "$file" ]]; then
      echo "$rel_doc:$line: $target: no such file"
      failures=$((failures + 1))
    elif [[ -n "$fragment" ]]; then
      if [[ "$file" != *.md ]]; then
        echo "$rel_doc:$line: $target: a #fragment on a file that is not Markdown"
        failures=$((failures + 1))
      elif ! anchors "$file" | grep -qxF -- "$fragment"; then
        echo "$rel_doc:$line: $target: no heading gives #$fragment in ${file#"$repo"/}"
        failures=$((failures + 1))
      fi
    fi
  done < <(links "$doc")
done
if ((checked == 0)); then
  echo "no relative link found in README.md and docs/: the check itself is broken"
  exit 1
fi
if ((failures > 0)); then
  echo "FAIL: $failures of $checked relative links do not resolve"
  exit 1
fi
echo "ok: $checked relative links resolve"
