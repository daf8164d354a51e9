#!/usr/bin/env bash
# Loads an HTML page in headless Chromium (Debian `chromium`), as a reader's browser would:
#   scripts/html-check.sh PAGE.html [SCREENSHOT.png [WIDTHxHEIGHT]]
# Prints the page's DOM after loading on standard output, writes a screenshot when asked, and
# exits 1 if the page wrote anything to the browser console (a script error, a failed resource,
# a console message), with those lines on stderr; 2 when Chromium is missing or fails.
set -euo pipefail
page=${1:?usage: html-check.sh PAGE.html [SCREENSHOT.png [WIDTHxHEIGHT]]}
shot=${2:-}
size=${3:-1200x2400}
command -v chromium >/dev/null || { echo "html-check: chromium is not installed (scripts/setup-deps.sh)" >&2; exit 2; }
profile=$(mktemp -d)
log=$(mktemp)
trap 'rm -rf "$profile" "$log"' EXIT
url="file://$(realpath "$page")"
flags=(--headless --no-sandbox --disable-gpu --disable-background-networking --disable-component-update
       --no-first-run --disable-sync --user-data-dir="$profile" --enable-logging=stderr --v=0)
timeout 120 chromium "${flags[@]}" --dump-dom "$url" 2>"$log" || { cat "$log" >&2; exit 2; }
if grep -q ":CONSOLE" "$log"; then
  grep ":CONSOLE" "$log" >&2
  exit 1
fi
if [ -n "$shot" ]; then
  timeout 120 chromium "${flags[@]}" --window-size="${size/x/,}" --hide-scrollbars --screenshot="$shot" "$url" \
    >/dev/null 2>"$log" || { cat "$log" >&2; exit 2; }
fi
