"""MACFUN plugins: machine-specific special functions (manual §5.6.7)."""
