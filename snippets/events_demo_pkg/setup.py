from setuptools import find_packages, setup

package_name = 'events_demo_pkg'

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
    description='Helper nodes for lesson 6.6 (events and processes): a sensor that '
                'loses its hardware, a node slow to stop.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'flaky_sensor = events_demo_pkg.flaky_sensor:main',
            'stubborn_node = events_demo_pkg.stubborn_node:main',
        ],
    },
)
