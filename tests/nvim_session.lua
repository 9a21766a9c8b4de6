-- A real editor session for tests/test_nvim.py: headless Neovim opens $RF_FILE,
-- starts `robotfix lsp` ($RF_CMD, a JSON list) with its built-in client, waits for
-- diagnostics, edits a line, asks for a hover and for code actions, and writes what
-- it saw, with times from vim.loop.hrtime (seconds), as JSON to $RF_OUT.
-- Neovim 0.8+ has vim.lsp.start; 0.7 (Debian 12) only start_client.
local now = function() return vim.loop.hrtime() / 1e9 end
local seen = { times = { lua = now() } }
local published = {}
local function env(name, default) return os.getenv(name) or default end

vim.cmd("edit " .. vim.fn.fnameescape(env("RF_FILE")))
local config = {
  name = "robotfix",
  cmd = vim.fn.json_decode(env("RF_CMD")),
  root_dir = vim.fn.fnamemodify(env("RF_FILE"), ":h"),
  handlers = {
    ["textDocument/publishDiagnostics"] = function(err, result, ctx, cfg)
      table.insert(published, { t = now(), diagnostics = result.diagnostics })
      return vim.lsp.handlers["textDocument/publishDiagnostics"](err, result, ctx, cfg)
    end,
  },
}
seen.times.start = now()
if vim.lsp.start then
  seen.client = vim.lsp.start(config)
else
  seen.client = vim.lsp.start_client(config)
  vim.lsp.buf_attach_client(0, seen.client)
end
local timeout = tonumber(env("RF_TIMEOUT_MS", "60000"))
local function published_count(n)
  vim.wait(timeout, function() return #published >= n end, 5)
  return published[n]
end

local opened = published_count(1)
seen.opened = opened and opened.diagnostics
seen.times.opened = opened and opened.t

-- the edit: line $RF_EDIT_LINE (1-based) becomes $RF_EDIT_TEXT
local line = tonumber(env("RF_EDIT_LINE", "1"))
seen.times.edit = now()
vim.api.nvim_buf_set_lines(0, line - 1, line, false, { env("RF_EDIT_TEXT", "") })
local edited = published_count(2)
seen.edited = edited and edited.diagnostics
seen.times.edited = edited and edited.t

local function request(method, params)
  local answers = vim.lsp.buf_request_sync(0, method, params, timeout) or {}
  for _, answer in pairs(answers) do
    return answer.result
  end
end
local document = vim.lsp.util.make_text_document_params()
local at = { line = tonumber(env("RF_AT_LINE", "0")), character = tonumber(env("RF_AT_COL", "0")) }
seen.times.hover = now()
seen.hover = request("textDocument/hover", { textDocument = document, position = at })
seen.times.hovered = now()
seen.actions = request("textDocument/codeAction", {
  textDocument = document,
  range = { start = at, ["end"] = at },
  context = { diagnostics = seen.edited or {} },
})
seen.times.acted = now()

local out = io.open(env("RF_OUT"), "w")
out:write(vim.fn.json_encode(seen))
out:close()
vim.lsp.stop_client(seen.client)
vim.wait(5000, function() return vim.lsp.get_client_by_id(seen.client) == nil end, 10)
vim.cmd("qa!")
