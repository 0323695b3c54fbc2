#!/bin/sh
# ctest `docs.citations`: every document the repository's files cite exists in the repository.
# A citation is a path ending in .md that names a folder ("docs/oracles.md",
# "reference/leb/FORMAT.md") or is written in capitals ("FORMAT.md": beside the citing file), and
# every relative Markdown link "](x.md)". It resolves from the repository root, from the citing
# file's folder, or, in a document, from docs/. A lower-case bare name that is no link is an output
# file ("bench.md"), not a citation.   check_citations.sh REPOSITORY_ROOT
set -u
cd "$1" || exit 2
missing=0
checked=0
files=$(git ls-files 2>/dev/null || find . -type f | sed 's|^\./||')
candidates=""
for f in $files; do
  case "$f" in
    *.cpp|*.h|*.cmake|*.md|*.txt|*.sh|*.frag|*.vert|*.glsl|*/run|CMakeLists.txt|*/CMakeLists.txt) ;;
    *) continue ;;
  esac
  case "$f" in tests/fuzz/regressions/*|tests/fuzz/dicts/*|cmake/check_citations.sh) continue ;; esac
  [ -f "$f" ] && candidates="$candidates $f"
done
# Only the files that name a .md at all, found by one grep (a few processes a file otherwise).
for f in $(grep -lF '.md' $candidates </dev/null); do
  dir=$(dirname "$f")
  for t in $( (grep -oE '[A-Za-z0-9_./-]*[A-Za-z0-9_-]+\.md' "$f"; grep -oE '\]\([^)# ]+\.md' "$f" | sed 's/^](//') | sort -u); do
    base=$(basename "$t" .md)
    case "$t" in
      */*) ;;
      *) if [ "$base" != "$(echo "$base" | tr 'a-z' 'A-Z')" ] && ! grep -qF "]($t" "$f"; then continue; fi ;;
    esac
    checked=$((checked + 1))
    if [ -e "$t" ] || [ -e "$dir/$t" ]; then continue; fi
    case "$f" in *.md) [ -e "docs/$t" ] && continue ;; esac
    echo "MISSING: $f cites $t"
    missing=$((missing + 1))
  done
done
if [ "$missing" -ne 0 ]; then
  echo "docs.citations: $missing citation(s) of documents that are not in the repository"
  exit 1
fi
echo "docs.citations: $checked citations, every one a file of the repository"
