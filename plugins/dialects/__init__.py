"""CAM dialects: what each CAM system writes, mapped onto the post's statements (issue 19)."""
