#!/usr/bin/env bash
# End-to-end tests of `mechkit serve` in a real browser: Playwright (npm `playwright-core`,
# which downloads no browser) driving Debian's headless Chromium.
#
#   bash tests/browser/run.sh [path/to/mechkit]      (default: target/debug/mechkit)
#
# Needs node (18 or later), npm (`npm ci` here when node_modules is missing) and Chromium at
# /usr/bin/chromium (or $CHROMIUM): `apt-get install -y chromium` on Debian, as CI does.
# Starts the server on a temporary copy of examples/ (port 0: a free one), runs
# app.test.mjs, and stops the server. Screenshots go to target/browser/;
# MECHKIT_SCREENSHOTS=docs/img refreshes the documentation's (serve_editor.png, serve_run.png).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
mechkit="$(realpath "${1:-$root/target/debug/mechkit}")"
export CHROMIUM="${CHROMIUM:-/usr/bin/chromium}"
[ -x "$mechkit" ] || { echo "browser tests: no mechkit binary at $mechkit (cargo build -p mechkit-cli)" >&2; exit 2; }
[ -x "$CHROMIUM" ] || { echo "browser tests: no Chromium at $CHROMIUM (apt-get install -y chromium)" >&2; exit 2; }

if [ ! -d "$here/node_modules/playwright-core" ]; then
    (cd "$here" && npm ci --no-audit --no-fund --loglevel=error)
fi

work="$(mktemp -d -t mechkit-browser-XXXXXX)"
server=""
cleanup() {
    if [ -n "$server" ] && kill -0 "$server" 2>/dev/null; then
        kill -TERM "$server"
        wait "$server" || true
    fi
    rm -rf "$work"
}
trap cleanup EXIT
cp -r "$root/examples" "$work/examples"
"$mechkit" serve --port 0 --dir "$work/examples" >"$work/serve.out" 2>"$work/serve.err" &
server=$!
url=""
for _ in $(seq 1 300); do
    url="$(sed -n 's/^mechkit serve: \(http[^ ]*\) .*/\1/p' "$work/serve.out")"
    [ -n "$url" ] && break
    kill -0 "$server" 2>/dev/null || { cat "$work/serve.err" >&2; exit 1; }
    sleep 0.1
done
[ -n "$url" ] || { echo "browser tests: mechkit serve printed no URL" >&2; cat "$work/serve.err" >&2; exit 1; }

export MECHKIT_URL="$url"
export MECHKIT_SCREENSHOTS="${MECHKIT_SCREENSHOTS:-$root/target/browser}"
mkdir -p "$MECHKIT_SCREENSHOTS"
status=0
node --test --test-reporter=spec "$here/app.test.mjs" || status=$?
if [ "$status" -ne 0 ]; then
    echo "--- mechkit serve's stderr" >&2
    cat "$work/serve.err" >&2
fi
exit "$status"
