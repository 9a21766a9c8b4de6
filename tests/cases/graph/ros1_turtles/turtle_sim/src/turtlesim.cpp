// A one-turtle simulator, modelled on ros_tutorials' turtlesim (roscpp).
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <turtlesim/Color.h>
#include <turtlesim/Pose.h>

void velocityCallback(const geometry_msgs::Twist::ConstPtr& vel)
{
  (void)vel;
}

bool clearCallback(std_srvs::Empty::Request&, std_srvs::Empty::Response&)
{
  return true;
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "turtlesim");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  double rate = 62.5;
  private_nh.param("update_rate", rate, 62.5);
  ros::Subscriber vel_sub = nh.subscribe("turtle1/cmd_vel", 1, velocityCallback);
  ros::Publisher pose_pub = nh.advertise<turtlesim::Pose>("turtle1/pose", 1);  // error: RF603
  ros::Publisher color_pub = private_nh.advertise<turtlesim::Color>("color_sensor", 1);
  ros::ServiceServer clear_srv = nh.advertiseService("clear", clearCallback);
  ros::spin();
  return 0;
}
