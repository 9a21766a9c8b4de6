#!/bin/sh
# Packages this extension as a .vsix (default: robotfix.vsix here; or the path given),
# with the npm registry's vscode-languageclient and @vscode/vsce. Needs node and npm.
set -eu
out=$(realpath -m "${1:-robotfix.vsix}")
cd "$(dirname "$0")"
if [ -f package-lock.json ]; then
  npm ci --no-audit --no-fund
else
  npm install --no-audit --no-fund
fi
# No repository or marketplace listing exists: this .vsix is installed from a file.
npx --no-install vsce package --allow-missing-repository --skip-license --out "$out"
