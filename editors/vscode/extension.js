// Starts `robotfix lsp` for Python files and ROS interface files (.msg, .srv, .action).
"use strict";

const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");
const { serverCommand } = require("./server-command");

let client;

function expandVariables(text) {
  const folder = vscode.workspace.workspaceFolders?.[0]?.uri.fsPath ?? "";
  return text
    .replace(/\$\{workspaceFolder\}/g, folder)
    .replace(/\$\{userHome\}/g, require("os").homedir());
}

async function start() {
  const settings = vscode.workspace.getConfiguration("robotfix");
  const { command, args } = serverCommand(settings, expandVariables);
  const serverOptions = { command, args };
  const clientOptions = {
    documentSelector: [
      { scheme: "file", language: "python" },
      { scheme: "file", pattern: "**/*.{msg,srv,action}" },
    ],
  };
  client = new LanguageClient("robotfix", "RobotFix", serverOptions, clientOptions);
  try {
    await client.start();
  } catch (err) {
    vscode.window.showErrorMessage(
      `RobotFix: could not start \`${[command, ...args].join(" ")}\` (${err.message ?? err}). ` +
        "Install robotfix with its lsp extra, or set robotfix.path.",
    );
  }
}

async function restart() {
  if (client) {
    await client.stop().catch(() => undefined);
    client = undefined;
  }
  await start();
}

exports.activate = async (context) => {
  context.subscriptions.push(
    vscode.commands.registerCommand("robotfix.restart", restart),
    vscode.workspace.onDidChangeConfiguration((event) => {
      if (event.affectsConfiguration("robotfix")) {
        restart();
      }
    }),
  );
  await start();
};

exports.deactivate = () => (client ? client.stop() : undefined);
