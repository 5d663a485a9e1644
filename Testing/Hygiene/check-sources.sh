#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# Tree hygiene (issue 17): every C++/CMake/shell/Python source carries the licence header, the C++ is
# formatted with the top-level .clang-format, and the size limits hold (library files <= 500 lines
# aside from generated tables, module .cxx files <= 150 lines, library functions <= 120 lines); the
# README stays a door (<= 15 kB) and every relative link of the Markdown files leads somewhere.
#   check-sources.sh <source-dir> licence|format|sizes|functions|docs
set -euo pipefail
root="$1"
cd "$root"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  files() { git ls-files -- "$@"; }
else
  files() { for p in "$@"; do find . -path ./build -prune -o -path "./$p" -print | sed 's|^\./||'; done; }
fi
status=0
case "$2" in
  licence)
    while read -r f; do
      case "$f" in Resources/*) continue ;; esac
      head -n 3 "$f" | grep -q "SPDX-License-Identifier: BSD-3-Clause" || { echo "no licence header: $f"; status=1; }
    done < <(files '*.h' '*.hxx' '*.cxx' 'CMakeLists.txt' '*/CMakeLists.txt' '*.cmake' '*.sh' '*.py')
    ;;
  format)
    command -v clang-format >/dev/null || { echo "clang-format is not installed (Utilities/install-deps.sh installs it)"; exit 1; }
    while read -r f; do
      clang-format --dry-run -Werror "$f" >/dev/null 2>&1 || { echo "not formatted with .clang-format: $f (clang-format -i $f)"; status=1; }
    done < <(files '*.h' '*.hxx' '*.cxx')
    ;;
  sizes)
    while read -r f; do
      case "$f" in */Testing/*|*/test/*|*Tables.h) continue ;; esac
      n=$(wc -l < "$f"); [ "$n" -le 500 ] || { echo "library file over 500 lines ($n): $f"; status=1; }
    done < <(files 'Libs/*.h' 'Libs/*.hxx' 'Libs/*.cxx')
    while read -r f; do
      case "$f" in */Testing/*) continue ;; esac
      n=$(wc -l < "$f"); [ "$n" -le 150 ] || { echo "module file over 150 lines ($n): $f"; status=1; }
    done < <(files 'Modules/CLI/*.cxx')
    ;;
  functions)
    command -v pmccabe >/dev/null || { echo "pmccabe is not installed (Utilities/install-deps.sh installs it)"; exit 1; }
    while read -r line; do
      echo "function over 120 lines: $line"; status=1
    done < <(files 'Libs/*.h' 'Libs/*.hxx' 'Libs/*.cxx' | grep -v -e '/Testing/' -e '/test/' -e 'Tables.h$' |
             xargs pmccabe 2>/dev/null | awk '$5 > 120 { print $5 " lines: " $6 " " $7 }')
    ;;
  docs)
    n=$(wc -c < README.md); [ "$n" -le 15000 ] || { echo "README.md is $n bytes (at most 15000: details go to docs/)"; status=1; }
    # GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens.
    anchors() { grep -E '^#+ ' "$1" | sed -E 's/^#+ //' | tr '[:upper:]' '[:lower:]' | sed -E 's/[^a-z0-9 _-]//g; s/ /-/g'; }
    while read -r f; do
      while read -r target; do
        case "$target" in http*|mailto:*) continue ;; esac
        path="${target%%#*}"; anchor=""
        [ "$path" != "$target" ] && anchor="${target#*#}"
        dest="$f"; [ -n "$path" ] && dest="$(dirname "$f")/$path"
        if [ ! -e "$dest" ]; then echo "broken link in $f: $target"; status=1; continue; fi
        if [ -n "$anchor" ] && ! anchors "$dest" | grep -qx -- "$anchor"; then
          echo "link in $f to a missing heading: $target"; status=1
        fi
      done < <(grep -oE '\]\([^) ]+\)' "$f" | sed -E 's/^\]\(//; s/\)$//')
    done < <(files '*.md')
    ;;
  *) echo "usage: check-sources.sh <source-dir> licence|format|sizes|functions|docs"; exit 2 ;;
esac
exit $status
