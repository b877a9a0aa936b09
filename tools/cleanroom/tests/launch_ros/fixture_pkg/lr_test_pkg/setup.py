from glob import glob

from setuptools import setup

package_name = 'lr_test_pkg'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/config', glob('config/*.yaml')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    entry_points={
        'console_scripts': [
            'noop = lr_test_pkg.nodes:noop',
            'lifecycle_talker = lr_test_pkg.nodes:lifecycle_talker',
        ],
    },
)
