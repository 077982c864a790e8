"""`gecent verify`: a tape read back by LinuxCNC's own interpreter and compared with the CL
path (docs/verify.md)."""
