"""The motion element (manual §3.4): rounding, linear moves, segmentation, circles."""
