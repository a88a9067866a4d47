-- Drives `umbrac lsp` from Neovim's built-in LSP client, headless, on a
-- program ($FILE) that requires a module beside it (lib.das): jumps to a
-- function's definition in the module, renames it across both files,
-- completes a struct's fields after `m.`. Writes `key<TAB>value` lines to
-- $OUT for tests/compiler/lsp.rs; quits in every case.
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
  local id = vim.lsp.start_client({ name = "umbrac", cmd = { os.getenv("UMBRAC"), "lsp" }, root_dir = vim.fn.fnamemodify(os.getenv("FILE"), ":h") })
  vim.lsp.buf_attach_client(buf, id)
  say("attached", vim.wait(20000, function() return vim.lsp.get_client_by_id(id).initialized end, 50))
  local function find(pat)
    for i, l in ipairs(vim.api.nvim_buf_get_lines(buf, 0, -1, false)) do
      local c = l:find(pat, 1, true)
      if c then return i - 1, c - 1 end
    end
  end
  local function request(method, params)
    local res = vim.lsp.buf_request_sync(buf, method, params, 20000) or {}
    return res[id] and res[id].result, res[id] and res[id].err
  end
  local uri = vim.uri_from_bufnr(buf)
  -- The first check has run once a query answers.
  vim.wait(20000, function()
    local r = request("textDocument/documentSymbol", { textDocument = { uri = uri } })
    return r and #r > 0
  end, 100)
  -- Definition of `tint`: in lib.das.
  local l, c = find("tint(")
  local def = request("textDocument/definition", { textDocument = { uri = uri }, position = { line = l, character = c + 1 } })
  say("definition", def and vim.uri_to_fname(def.uri) .. ":" .. def.range.start.line .. ":" .. def.range.start.character or "none")
  -- Rename `tint` to `shade_it` in both files.
  local edit, rerr = request("textDocument/rename", { textDocument = { uri = uri }, position = { line = l, character = c + 1 }, newName = "shade_it" })
  if edit then vim.lsp.util.apply_workspace_edit(edit, "utf-16") end
  say("rename_error", rerr and rerr.message or "none")
  say("main_after", table.concat(vim.api.nvim_buf_get_lines(buf, 0, -1, false), "\n"))
  local lib = vim.fn.bufnr(vim.fn.fnamemodify(os.getenv("FILE"), ":h") .. "/lib.das")
  say("lib_after", lib > 0 and table.concat(vim.api.nvim_buf_get_lines(lib, 0, -1, false), "\n") or "not loaded")
  -- Complete after `m.` on a new line typed inside `fs`.
  local rl = find("m.rough = 0.5")
  vim.api.nvim_buf_set_lines(buf, rl + 1, rl + 1, false, { "    let q = m." })
  local items = request("textDocument/completion", { textDocument = { uri = uri }, position = { line = rl + 1, character = #"    let q = m." } })
  local labels = {}
  for _, it in ipairs((items and (items.items or items)) or {}) do table.insert(labels, it.label) end
  table.sort(labels)
  say("completion", table.concat(labels, ","))
end)
if not ok then say("lua_error", err) end
finish()
