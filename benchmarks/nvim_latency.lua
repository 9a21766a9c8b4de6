-- Headless Neovim for benchmarks/nvim_latency.py: opens $RF_FILE, starts the server
-- ($RF_CMD, JSON) with the built-in client (debounce $RF_DEBOUNCE ms, Neovim's
-- default 150), waits for diagnostics, makes $RF_EDITS edits of line $RF_EDIT_LINE
-- (alternately $RF_EDIT_A and $RF_EDIT_B, $RF_PAUSE ms apart), asks for a hover and
-- code actions at $RF_AT (line,col, 0-based); times (vim.loop.hrtime) to $RF_OUT.
local now = function() return vim.loop.hrtime() / 1e9 end
local T = { lua = now(), edits = {} }
local function env(name, default) return os.getenv(name) or default end
vim.cmd("edit " .. vim.fn.fnameescape(env("RF_FILE")))
local published = {}
local config = {
  name = "robotfix",
  cmd = vim.fn.json_decode(env("RF_CMD")),
  root_dir = vim.fn.fnamemodify(env("RF_FILE"), ":h"),
  flags = { debounce_text_changes = tonumber(env("RF_DEBOUNCE", "150")) },
  handlers = {
    ["textDocument/publishDiagnostics"] = function(err, result, ctx, cfg)
      table.insert(published, { t = now(), n = #result.diagnostics })
      return vim.lsp.handlers["textDocument/publishDiagnostics"](err, result, ctx, cfg)
    end,
  },
}
T.start = now()
local id = vim.lsp.start_client(config)
vim.lsp.buf_attach_client(0, id)
local function publish(n)
  vim.wait(60000, function() return #published >= n end, 1)
  return published[n] and published[n].t
end
T.opened = publish(1)
T.count = published[1] and published[1].n
local line = tonumber(env("RF_EDIT_LINE", "0"))
if line == 0 then line = vim.api.nvim_buf_line_count(0) end
local texts = { env("RF_EDIT_A", "# a"), env("RF_EDIT_B", "# b") }
for i = 1, tonumber(env("RF_EDITS", "6")) do
  vim.wait(tonumber(env("RF_PAUSE", "300")))
  local before, t = #published, now()
  vim.api.nvim_buf_set_lines(0, line - 1, line, false, { texts[i % 2 + 1] })
  table.insert(T.edits, { sent = t, got = publish(before + 1) })
end
local at = vim.split(env("RF_AT", "0,0"), ",")
local params = {
  textDocument = vim.lsp.util.make_text_document_params(),
  position = { line = tonumber(at[1]), character = tonumber(at[2]) },
}
T.hover = { now() }
vim.lsp.buf_request_sync(0, "textDocument/hover", params, 20000)
T.hover[2] = now()
params.range = { start = params.position, ["end"] = params.position }
params.context = { diagnostics = {} }
T.action = { now() }
local answers = vim.lsp.buf_request_sync(0, "textDocument/codeAction", params, 20000)
T.action[2] = now()
T.titles = {}
for _, answer in pairs(answers or {}) do
  for _, action in ipairs(answer.result or {}) do table.insert(T.titles, action.title) end
end
local out = io.open(env("RF_OUT"), "w")
out:write(vim.fn.json_encode(T))
out:close()
vim.lsp.stop_client(id)
vim.wait(2000, function() return vim.lsp.get_client_by_id(id) == nil end, 10)
vim.cmd("qa!")
