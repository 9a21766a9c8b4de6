"""ROS interfaces: interface files, the standard message catalog, REP 103 units."""
