"""RF301 points at the read: the caret is under the unbound name, at the line of the
read in a statement written over several lines, and the statement is shown whole. A
name the function assigns only on another branch, or only later, says so (newuser2
§7 item 9: "`self.logwarn(` reads `dt`, which is not defined here")."""
import rospy


class Odometry:
    def on_timer(self, stale: bool) -> None:
        if stale:
            dt = rospy.get_time()
            rospy.loginfo("%f" % dt)
        else:
            self.logwarn(
                "No encoder messages for %.2f seconds" % dt  # error: RF301 "% dt)` reads `dt`, which is assigned only on other paths (line 11): here it raises UnboundLocalError"
            )

    def on_tick(self, ok: bool) -> None:
        if ok:
            period = 0.1
        self.logwarn(
            "period %f",
            period,  # error: RF301 "which is not assigned on every path to this line"
        )

    def later(self) -> None:
        print(speed)  # error: RF301 "`print(speed)` reads `speed`, which is assigned only after this line (line 28)"
        speed = 2.0

    def logwarn(self, *args: object) -> None:
        pass
