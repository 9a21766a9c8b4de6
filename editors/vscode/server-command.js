// The command line that starts the language server, from the extension's settings.
// Kept apart from extension.js (no `vscode` import) so that tests can run it in node.
"use strict";

const DEFAULT_PATH = "robotfix";
const DEFAULT_ARGS = ["lsp"];

/**
 * @param {{ get: (key: string) => unknown }} settings the `robotfix` section
 * @param {(text: string) => string} [expand] replaces `${workspaceFolder}` and the like
 * @returns {{ command: string, args: string[] }}
 */
function serverCommand(settings, expand = (text) => text) {
  const path = settings.get("path");
  const args = settings.get("args");
  return {
    command: expand(typeof path === "string" && path.trim() ? path.trim() : DEFAULT_PATH),
    args: (Array.isArray(args) ? args.filter((a) => typeof a === "string") : DEFAULT_ARGS)
      .map(expand),
  };
}

module.exports = { serverCommand, DEFAULT_PATH, DEFAULT_ARGS };
