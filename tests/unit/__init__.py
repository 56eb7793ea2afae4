"""Unit tests, one folder per layer of the library and per part of the repository (tests/README.md)."""
