"""Machine packs: the Standard Machine and the manual's sample machines (§5.6.8)."""
