from setuptools import find_packages, setup

package_name = 'capstone_robot'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='ROS 2 launch textbook',
    maintainer_email='textbook@example.com',
    description='The nodes of the capstone robot system (chapter 7): one turtle sensed, '
                'estimated, planned for, steered and kept off the walls.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'wall_sensor = capstone_robot.wall_sensor:main',
            'pose_estimator = capstone_robot.pose_estimator:main',
            'patrol_planner = capstone_robot.patrol_planner:main',
            'controller = capstone_robot.controller:main',
            'safety_monitor = capstone_robot.safety_monitor:main',
            'mission_recorder = capstone_robot.mission_recorder:main',
            'spawner = capstone_robot.spawner:main',
            'sim_watchdog = capstone_robot.sim_watchdog:main',
        ],
    },
)
