"""The examples of docs/ run as printed."""
