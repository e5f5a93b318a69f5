# SPDX-License-Identifier: GPL-3.0-or-later
"""Type stub of kinstab._report, the design report (python/report/ReportModule.cpp)."""

def write_report(project: str, pdf_path: str, page: str = "a4", figure_grid: int = 41) -> str: ...
