#!/usr/bin/env bash
# Every command example of the README and of each page under docs/, run as the page shows it
# (tests/support/doc_examples.py: extracted from the page itself, in order, in a scratch
# folder; a non-zero exit fails unless the example's comment announces it). EXAMPLES=small
# (the default) runs long examples at a reduced size, EXAMPLES=full as written
# (docs/conventions.md, "The examples are tested").
#   bash doc_examples.sh --list | PAGE     (needs CMP_BIN, CMP_SRC)
set -uo pipefail
src=${CMP_SRC:-$(cd "$(dirname "$0")/../.." && pwd)}
if [[ ${1:-} == --list ]]; then
  (cd "$src" && ls README.md docs/*.md) | sed 's/\.md$//; s|^docs/||'
  exit 0
fi
page=${1:?PAGE}
file="$src/docs/$page.md"
[ "$page" = README ] && file="$src/README.md"
[ -f "$file" ] || { echo "FAIL: no page $file" >&2; exit 1; }
exec /usr/bin/python3 "$src/tests/support/doc_examples.py" "$file" --bin "${CMP_BIN:?set CMP_BIN}" \
  --src "$src" --size "${EXAMPLES:-small}"
