"""crumple compare: Crumple histories against LS-DYNA ASCII output (docs/validation.md)."""
