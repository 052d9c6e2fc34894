#!/usr/bin/env python3
"""Reads an exported folder with Python's own parsers (PyYAML, ElementTree, py_compile), not
rigdesign's, and checks what a hostile rig name, path or link name must not change:
  parse_export.py FOLDER MOUNT_IDS PARENT_LINK
MOUNT_IDS: comma-separated ids the rig file declares; PARENT_LINK: the link the exported macro
hangs every added joint from by default. Exit 0 when every file parses and says what it should."""
import py_compile
import sys
import xml.etree.ElementTree as ET

import yaml

folder, mounts, parent = sys.argv[1], sys.argv[2].split(','), sys.argv[3]
problems = []


def keys_of(node):
    if isinstance(node, dict):
        for key, value in node.items():
            yield key
            yield from keys_of(value)
    elif isinstance(node, list):
        for value in node:
            yield from keys_of(value)


nav2 = yaml.safe_load(open(folder + '/nav2_costmap.yaml', encoding='utf-8'))
parameters = nav2['local_costmap']['local_costmap']['ros__parameters']
layer = parameters.get('voxel_layer') or parameters['obstacle_layer']
sources = str(layer['observation_sources']).split()
if sorted(sources) != sorted(mounts):
    problems.append('nav2 sources %r, rig mounts %r' % (sources, mounts))
for source in sources:
    if source not in layer:
        problems.append('source %s has no parameters' % source)
if 'injected' in set(keys_of(nav2)):
    problems.append('a key from the rig name reached nav2_costmap.yaml')

filters = yaml.safe_load(open(folder + '/self_filters.yaml', encoding='utf-8'))
if filters is not None and 'injected' in set(keys_of(filters)):
    problems.append('a key from the rig name reached self_filters.yaml')

robot = ET.parse(folder + '/sensors.urdf.xacro').getroot()
joints = [j for j in robot.iter('joint')]
names = [j.get('name') for j in joints]
if len(names) != len(set(names)):
    problems.append('duplicate joint names %r' % names)
macros = [e for e in robot.iter() if e.tag.endswith('}macro')]
params = macros[0].get('params', '').split() if macros else []
if 'parent:=' + parent not in params:
    problems.append('the macro does not default its parent to %r (params: %r)' % (parent, params))
for joint in joints:
    if joint.find('parent') is None or joint.find('parent').get('link') != '${parent}':
        problems.append('joint %r does not hang from the macro parent' % joint.get('name'))

py_compile.compile(folder + '/self_filters.launch.py', doraise=True)

# The Gazebo macro: one <sensor> per mount, named after it; the bridge: one entry per mount,
# then the simulation clock.
gazebo = ET.parse(folder + '/sensors.gazebo.xacro').getroot()
sensor_names = sorted(s.get('name') for s in gazebo.iter('sensor'))
if sensor_names != sorted(mounts):
    problems.append('Gazebo sensors %r, rig mounts %r' % (sensor_names, mounts))
bridge = yaml.safe_load(open(folder + '/bridge.yaml', encoding='utf-8'))
if (not isinstance(bridge, list) or len(bridge) != len(mounts) + 1
        or bridge[-1].get('ros_topic_name') != '/clock'):
    problems.append('bridge.yaml holds %r, not one entry per mount and the clock' % (bridge,))
elif 'injected' in set(keys_of(bridge)):
    problems.append('a key from the rig name reached bridge.yaml')

for problem in problems:
    print(problem)
sys.exit(1 if problems else 0)
