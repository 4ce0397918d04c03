"""Write the reproduction report (placeholder replaced in issue 8)."""
