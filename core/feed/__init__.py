"""Feedrates (manual §4.1): the contouring feed command and rapid traverse."""
