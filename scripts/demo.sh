#!/usr/bin/env bash
# The demo: builds the page (scripts/build-web.sh) and serves it on http://127.0.0.1:8000.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build-web.sh
echo "serving http://127.0.0.1:8000 (Ctrl-C stops)"
exec python3 -m http.server 8000 --bind 127.0.0.1 --directory web
