#!/usr/bin/env bash
# Seeds each fuzz target's corpus with the samples, the test fixtures and the
# outside corpus (../shared/corpus, or $SINUPREP_CORPUS). The corpus folders
# are generated, not committed.
set -euo pipefail
cd "$(dirname "$0")"
outside="${SINUPREP_CORPUS:-../../shared/corpus}"
for target in parse_print check rewrite archive fmt run; do
  mkdir -p "corpus/$target"
  find ../samples ../tests/fixtures "$outside" -type f ! -name '*.md' ! -name '*.snap' 2>/dev/null |
    while read -r file; do cp "$file" "corpus/$target/$(echo "$file" | sed 's|^\(\.\./\)*||; s|/|_|g')"; done
done
