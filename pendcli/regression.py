"""CI regression of tables (placeholder replaced in issue 8)."""
