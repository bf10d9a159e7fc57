#!/usr/bin/env bash
# usage: compare.sh BEFORE_DIR AFTER_DIR — byte-compare every output except report PDFs (compared as text),
# xlsx (every zip member compared, except docProps/core.xml which holds the time of writing) and logs
A=$1; B=$2; bad=0; n=0
while IFS= read -r f; do
  rel=${f#$A/}
  case "$rel" in *.log|*/.cache/*|.cache/*|*manifest*|*.portfolio.json) continue;; esac
  n=$((n+1))
  if [ ! -e "$B/$rel" ]; then echo "MISSING $rel"; bad=1; continue; fi
  case "$rel" in
    *.xlsx) if ! python3 "$(dirname "$0")/xlsx_same.py" "$f" "$B/$rel"; then echo "XLSX CONTENT DIFFERS $rel"; bad=1; fi;;
    *.pdf) if ! diff -q <(pdftotext -layout "$f" - 2>/dev/null) <(pdftotext -layout "$B/$rel" - 2>/dev/null) >/dev/null; then echo "PDF TEXT DIFFERS $rel"; bad=1; fi;;
    *) if ! cmp -s "$f" "$B/$rel"; then echo "DIFFERS $rel"; bad=1; fi;;
  esac
done < <(find "$A" -type f | sort)
while IFS= read -r f; do rel=${f#$B/}; case "$rel" in *.log|*/.cache/*|.cache/*|*manifest*|*.portfolio.json) continue;; esac; [ -e "$A/$rel" ] || { echo "EXTRA $rel"; bad=1; }; done < <(find "$B" -type f | sort)
echo "compared $n files: $([ $bad = 0 ] && echo identical || echo DIFFERENT)"
exit $bad
