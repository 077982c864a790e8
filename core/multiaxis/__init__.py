"""Multiaxis machines (manual §4.2, spec 05 §8): the transform classes that carry a CL
point and its tool axis to the machine's linear and rotary axes and back."""
