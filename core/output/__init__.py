"""The output element (manual §3.5): command blocks, tape image and printed listing."""
