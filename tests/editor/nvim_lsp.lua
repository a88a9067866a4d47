-- Drives `umbrac lsp` from Neovim's built-in LSP client (0.7 and later),
-- headless: opens $FILE, introduces an error, waits for the diagnostic,
-- undoes it, waits for the diagnostics to clear, hovers a name. Writes
-- what it saw to $OUT, one `key<TAB>value` a line, for the Rust test
-- (tests/compiler/lsp.rs) to check; quits in every case.
local out = {}
local function say(k, v) table.insert(out, k .. "\t" .. tostring(v):gsub("\n", "\\n")) end
local function finish()
  local f = io.open(os.getenv("OUT"), "w")
  f:write(table.concat(out, "\n") .. "\n")
  f:close()
  vim.cmd("qa!")
end

local ok, err = pcall(function()
  vim.cmd("edit " .. vim.fn.fnameescape(os.getenv("FILE")))
  local buf = vim.api.nvim_get_current_buf()
  local id = vim.lsp.start_client({
    name = "umbrac",
    cmd = { os.getenv("UMBRAC"), "lsp" },
    root_dir = vim.fn.fnamemodify(os.getenv("FILE"), ":h"),
    init_options = { targets = { "glsl330", "wgsl" } },
  })
  vim.lsp.buf_attach_client(buf, id)
  local function find(pat)
    for i, l in ipairs(vim.api.nvim_buf_get_lines(buf, 0, -1, false)) do
      local c = l:find(pat, 1, true)
      if c then return i - 1, c - 1, l end
    end
  end
  say("attached", vim.wait(20000, function() return vim.lsp.buf_is_attached(buf, id) and vim.lsp.get_client_by_id(id).initialized end, 50))
  -- An unknown name where `v_color` is read.
  local line, col, text = find("f_color = v_color")
  local bad_col = col + #"f_color = "
  vim.api.nvim_buf_set_lines(buf, line, line + 1, false, { (text:gsub("v_color", "v_colr")) })
  say("error_line", line)
  say("error_col", bad_col)
  local got = vim.wait(30000, function() return #vim.diagnostic.get(buf) > 0 end, 50)
  local d = vim.diagnostic.get(buf)[1] or {}
  say("diag_seen", got)
  say("diag_line", d.lnum)
  say("diag_col", d.col)
  say("diag_message", d.message)
  -- Undo: the diagnostics go.
  vim.api.nvim_buf_set_lines(buf, line, line + 1, false, { text })
  say("cleared", vim.wait(30000, function() return #vim.diagnostic.get(buf) == 0 end, 50))
  -- Hover `u_angle` in `cos(u_angle)`.
  local hl, hc = find("cos(u_angle)")
  local params = { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = hl, character = hc + 5 } }
  local res = vim.lsp.buf_request_sync(buf, "textDocument/hover", params, 20000) or {}
  local r = res[id] and res[id].result
  say("hover", r and r.contents and r.contents.value or "none")
end)
if not ok then say("lua_error", err) end
finish()
