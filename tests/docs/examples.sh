#!/usr/bin/env bash
# The manual's examples still run, and its links lead somewhere (docs/tests.md, "The manual's
# examples"). Usage: examples.sh COLLIDE SOURCE_DIR
#
# What is run, in README.md and docs/**/*.md:
#   - in a fenced code block whose info string is `sh`, every line whose first word is
#     `collide`: it runs in bash, with `collide` this build's command, in a fresh directory
#     holding a copy of the source tree's lessons/ (so lessons/solve/kane-rod.toml resolves and
#     `-o out/x` writes there; COLLIDE_LESSONS points at the copy). It must exit 0, or N when
#     its comment ends in `exits N`. A page's lines run in order in one directory, so a line
#     may read what an earlier one wrote. Other lines (scripts/*.sh, apt, cmake, chromium,
#     node, ...) are not run; nor is any block marked `console`, `text`, `toml`, `json`, ...
#   - a fenced block whose info string is `python`, as one program, in the same kind of
#     directory, when this build has the Python module (build/python) and /usr/bin/python3 can
#     import it; otherwise one line says the Python examples were skipped.
# What is checked: every code fence is closed; every Markdown link or image `](target)` outside code to a local file or
# folder exists (relative to the page); a `#anchor` into a Markdown page names one of its
# headings (GitHub's slugs: lower case, punctuation dropped, spaces as hyphens).
# A failure names the page and line. The run takes some 30 s (a few renders at 480p and 720p).
set -uo pipefail
collide=$(realpath "$1")
source_dir=$(realpath "$2")
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

work=$(mktemp -d "${TMPDIR:-/tmp}/collide-docs.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/bin"
ln -s "$collide" "$work/bin/collide"

cd "$source_dir" || exit 1
pages=(README.md)
while IFS= read -r f; do pages+=("$f"); done < <(find docs -name '*.md' | sort)

# A fresh directory with the lessons, for one page's examples.
fresh_dir() {
  local d
  d=$(mktemp -d "$work/run.XXXXXX")
  cp -r "$source_dir/lessons" "$d/lessons"
  echo "$d"
}

# ---- Code fences: an unclosed one swallows the rest of the page ----
for page in "${pages[@]}"; do
  fences=$(grep -c '^[[:space:]]*```' "$page")
  ((fences % 2 == 0)) || fail "$page: $fences code fences, one left open"
done

# ---- Shell examples ----
commands=0
for page in "${pages[@]}"; do
  dir=""
  in_block=0 lang="" lineno=0
  while IFS= read -r line || [[ -n $line ]]; do
    lineno=$((lineno + 1))
    if [[ $line =~ ^[[:space:]]*\`\`\`(.*)$ ]]; then
      if [[ $in_block -eq 0 ]]; then in_block=1 lang=${BASH_REMATCH[1]}; else in_block=0 lang=""; fi
      continue
    fi
    [[ $in_block -eq 1 && $lang == sh ]] || continue
    [[ $line =~ ^collide[[:space:]] ]] || continue
    expected=0
    [[ $line =~ \#.*exits[[:space:]]+([0-9]+)[[:space:]]*$ ]] && expected=${BASH_REMATCH[1]}
    [[ -n $dir ]] || dir=$(fresh_dir)
    commands=$((commands + 1))
    out=$(cd "$dir" && PATH="$work/bin:$PATH" COLLIDE_LESSONS="$dir/lessons" bash -c "$line" </dev/null 2>&1)
    code=$?
    if [[ $code -ne $expected ]]; then
      fail "$page:$lineno: exit $code (expected $expected): $line"
      head -n 10 <<<"$out" | sed 's/^/    /'
    fi
  done <"$page"
done
echo "ran $commands shell examples"

# ---- Python examples ----
build_python=$(dirname "$(dirname "$collide")")/python
if [[ -d $build_python ]] && PYTHONPATH=$build_python /usr/bin/python3 -c 'import collide' 2>/dev/null; then
  blocks=0
  for page in "${pages[@]}"; do
    # Each ```python block as a file of its own, the page's line numbers kept by blank lines.
    awk -v out="$work/py" -v page="$(basename "$page")" '
      /^[[:space:]]*```python[[:space:]]*$/ { n++; f = out "." page "." n ".py";
                                             for (i = 1; i <= NR; i++) print "" > f; inb = 1; next }
      inb && /^[[:space:]]*```/ { inb = 0; close(f); next }
      inb { print > f }' "$page"
    for f in "$work/py.$(basename "$page")".*.py; do
      [[ -f $f ]] || continue
      blocks=$((blocks + 1))
      dir=$(fresh_dir)
      if ! out=$(cd "$dir" && PYTHONPATH=$build_python COLLIDE_LESSONS="$dir/lessons" /usr/bin/python3 "$f" 2>&1); then
        at=$(grep -o "\"$f\", line [0-9]*" <<<"$out" | tail -n 1 | grep -o '[0-9]*$')
        fail "$page:${at:-?}: the python block fails"
        tail -n 5 <<<"$out" | sed 's/^/    /'
      fi
      rm -f "$f"
    done
  done
  echo "ran $blocks Python examples"
else
  echo "skipped the Python examples: no Python module in $build_python (or /usr/bin/python3 cannot import it)"
fi

# ---- Links ----
# GitHub's anchor of a heading: lower case, what is not a letter, digit, space, - or _ dropped,
# spaces as hyphens.
slugs() {
  awk '/^[[:space:]]*```/ { inb = !inb; next } !inb && /^#+ / { sub(/^#+ /, ""); print }' "$1" |
    tr 'A-Z' 'a-z' | sed 's/[^a-z0-9 _-]//g; s/ /-/g'
}
links=0
for page in "${pages[@]}"; do
  base=$(dirname "$page")
  # Links outside code blocks and outside `code`.
  while IFS=$'\t' read -r lineno target; do
    case $target in http://* | https://* | mailto:*) continue ;; esac
    links=$((links + 1))
    path=${target%%#*}
    anchor=""
    [[ $target == *"#"* ]] && anchor=${target#*#}
    if [[ -z $path ]]; then file=$page; else file=$base/$path; fi
    if [[ ! -e $file ]]; then
      fail "$page:$lineno: link to a missing file: $target"
      continue
    fi
    if [[ -n $anchor && $file == *.md ]] && ! slugs "$file" | grep -qxF -- "$anchor"; then
      fail "$page:$lineno: no heading for the anchor: $target"
    fi
  done < <(awk '/^[[:space:]]*```/ { inb = !inb; next }
                !inb { line = $0; gsub(/`[^`]*`/, "", line);
                       while (match(line, /\]\([^) ]+\)/)) {
                         print NR "\t" substr(line, RSTART + 2, RLENGTH - 3);
                         line = substr(line, RSTART + RLENGTH) } }' "$page")
done
echo "checked $links links in ${#pages[@]} pages"

[[ $failures -eq 0 ]] && echo "every example runs and every link resolves"
[[ $failures -eq 0 ]]
