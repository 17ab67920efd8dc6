// Starts `sinuprep lsp` for Sinumerik programs; everything an editor shows
// (findings, hovers, symbols, fixes) comes from the server.
const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const command = vscode.workspace.getConfiguration("sinuprep").get("path", "sinuprep");
  const server = { command, args: ["lsp"] };
  client = new LanguageClient(
    "sinuprep",
    "sinuprep",
    { run: server, debug: server },
    {
      documentSelector: [{ language: "sinumerik" }],
      synchronize: {
        // Settings, HEAD_DEF and definition files change what every program reads.
        fileEvents: vscode.workspace.createFileSystemWatcher("**/{sinuprep.toml,*.SPF,*.spf,*.DEF,*.def}"),
      },
    }
  );
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
