"""CL reader plugins: APT source text and binary CL files (manual §3.3)."""
