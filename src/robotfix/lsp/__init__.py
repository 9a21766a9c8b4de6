"""The language server: `rpc` (JSON-RPC over stdio, stdlib only), `documents` (the
editor's buffers), `server` (the LSP methods over `api`)."""
