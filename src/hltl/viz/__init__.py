"""Pictures: Gantt charts, scene animations and spec trees."""
