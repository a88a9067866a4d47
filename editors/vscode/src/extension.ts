// A thin client of `umbrac lsp`: it starts the server, passes the
// `umbrac.*` settings as initialization options, and shows a target's
// output through the server's `umbrac.output` command. Everything else
// is the server's (docs/editor.md).
import * as vscode from "vscode";
import { LanguageClient, LanguageClientOptions, ServerOptions } from "vscode-languageclient/node";

let client: LanguageClient | undefined;

/// The settings as `umbrac lsp` reads them (docs/editor.md, "Configuration").
function initializationOptions(): Record<string, unknown> {
  const c = vscode.workspace.getConfiguration("umbrac");
  const out: Record<string, unknown> = {};
  const set = (key: string, value: unknown) => {
    const empty = value === null || value === undefined || (Array.isArray(value) && value.length === 0) ||
      (typeof value === "object" && !Array.isArray(value) && Object.keys(value as object).length === 0);
    if (!empty) out[key] = value;
  };
  set("targets", c.get<string[]>("targets"));
  set("includeDirs", c.get<string[]>("includeDirs"));
  set("daslangRoot", c.get<string | null>("daslangRoot"));
  set("daslib", c.get<string | null>("daslib"));
  set("modules", c.get<Record<string, string>>("modules"));
  set("defines", c.get<string[]>("defines"));
  set("limits", c.get<Record<string, number>>("limits"));
  if (c.get<boolean>("strictLimits")) out.strictLimits = true;
  return out;
}

function start(): LanguageClient {
  const command = vscode.workspace.getConfiguration("umbrac").get<string>("path") || "umbrac";
  const serverOptions: ServerOptions = { command, args: ["lsp"] };
  const clientOptions: LanguageClientOptions = {
    documentSelector: [{ scheme: "file", language: "daslang" }],
    initializationOptions: initializationOptions(),
    synchronize: { fileEvents: vscode.workspace.createFileSystemWatcher("**/{*.das,umbrac.toml}") },
  };
  const c = new LanguageClient("umbrac", "umbrac", serverOptions, clientOptions);
  void c.start();
  return c;
}

/// What the server's `umbrac.output` command answers.
interface Output {
  files: { name: string; text: string }[];
}

async function showOutput(): Promise<void> {
  const editor = vscode.window.activeTextEditor;
  if (!client || !editor || editor.document.languageId !== "daslang") {
    void vscode.window.showWarningMessage("umbrac: open a .das file first");
    return;
  }
  const target = await vscode.window.showQuickPick(["glsl330", "gles300", "glsl430", "gles310", "wgsl"], { placeHolder: "the target whose output to show" });
  if (!target) return;
  try {
    const out = (await client.sendRequest("workspace/executeCommand", {
      command: "umbrac.output",
      arguments: [editor.document.uri.toString(), target],
    })) as Output;
    const text = out.files.map((f) => (out.files.length > 1 ? `// ---- ${f.name}\n${f.text}` : f.text)).join("\n");
    const doc = await vscode.workspace.openTextDocument({ content: text, language: target === "wgsl" ? "wgsl" : "glsl" });
    await vscode.window.showTextDocument(doc, { preview: true, viewColumn: vscode.ViewColumn.Beside });
  } catch (e) {
    void vscode.window.showErrorMessage(`umbrac: ${e instanceof Error ? e.message : String(e)}`);
  }
}

export function activate(context: vscode.ExtensionContext): void {
  client = start();
  context.subscriptions.push(
    vscode.commands.registerCommand("umbrac.showOutput", showOutput),
    vscode.commands.registerCommand("umbrac.restart", async () => {
      await client?.stop();
      client = start();
    }),
    // New settings take a new server (initialization options are read once).
    vscode.workspace.onDidChangeConfiguration(async (e) => {
      if (e.affectsConfiguration("umbrac")) {
        await client?.stop();
        client = start();
      }
    }),
  );
}

export async function deactivate(): Promise<void> {
  await client?.stop();
}
