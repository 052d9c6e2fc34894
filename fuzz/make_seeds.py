#!/usr/bin/env python3
"""Writes small synthetic seed inputs for the fuzz targets whose bundled files are too large
to mutate quickly or do not exist (clouds in every PCD/PLY encoding, tiny meshes, a PGM map,
logs, pipelines). scripts/fuzz.sh adds the bundled files (rigs/, sensors.yaml, data/) beside
them. Usage: make_seeds.py OUT_FOLDER"""
import os
import struct
import sys


def lzf_compress(data: bytes) -> bytes:
    """LZF as liblzf writes it: literal runs (control < 32) and back references (length in the
    control's top 3 bits, 7 = one more length byte), offsets up to 8191."""
    out = bytearray()
    literals = bytearray()
    table = {}
    i = 0

    def flush():
        while literals:
            run = literals[:32]
            out.append(len(run) - 1)
            out.extend(run)
            del literals[:32]

    while i < len(data):
        key = data[i:i + 3]
        ref = table.get(key) if len(key) == 3 else None
        if len(key) == 3:
            table[key] = i
        if ref is not None and 0 < i - ref - 1 < 8192:
            length = 3
            while i + length < len(data) and length < 264 and data[ref + length] == data[i + length]:
                length += 1
            flush()
            offset = i - ref - 1
            encoded = length - 2
            if encoded < 7:
                out.append((encoded << 5) | (offset >> 8))
            else:
                out.append((7 << 5) | (offset >> 8))
                out.append(encoded - 7)
            out.append(offset & 0xFF)
            i += length
        else:
            literals.append(data[i])
            i += 1
    flush()
    return bytes(out)


POINTS = [(0.5 * i, -0.25 * i, 0.1 * (i % 3), 0x00FF8000 + i) for i in range(12)]
POINTS[5] = (float("nan"), float("nan"), float("nan"), 0)


def pcd_header(data: str, width: int, height: int) -> bytes:
    return ("# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z rgb\n"
            "SIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
            f"WIDTH {width}\nHEIGHT {height}\nVIEWPOINT 0 0 0 1 0 0 0\n"
            f"POINTS {width * height}\nDATA {data}\n").encode()


def pcd_seeds():
    ascii_body = "".join(f"{x} {y} {z} {c}\n" for x, y, z, c in POINTS).encode()
    yield "ascii.pcd", pcd_header("ascii", 12, 1) + ascii_body
    binary = b"".join(struct.pack("<fffI", *p) for p in POINTS)
    yield "binary_organized.pcd", pcd_header("binary", 4, 3) + binary
    # binary_compressed stores each field's column in turn, then compresses (PCL's layout).
    columns = b"".join(
        b"".join(struct.pack("<f" if k < 3 else "<I", p[k]) for p in POINTS) for k in range(4))
    packed = lzf_compress(columns)
    yield "binary_compressed.pcd", (pcd_header("binary_compressed", 12, 1) +
                                    struct.pack("<II", len(packed), len(columns)) + packed)
    yield "xyz_double.pcd", (
        b"VERSION .7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n"
        b"POINTS 2\nDATA binary\n" + struct.pack("<6d", 1, 2, 3, -1, -2, -3))


def ply_seeds():
    head = "ply\nformat {} 1.0\ncomment seed\nelement vertex 12\nproperty float x\n" \
           "property float y\nproperty float z\nproperty uchar intensity\n" \
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    body = "".join(f"{x} {y} {z} {i}\n" for i, (x, y, z, _) in enumerate(POINTS)) + "3 0 1 2\n"
    yield "ascii.ply", (head.format("ascii") + body).encode()
    for name, order in (("binary_little_endian", "<"), ("binary_big_endian", ">")):
        data = b"".join(struct.pack(order + "fffB", x, y, z, i & 0xFF)
                        for i, (x, y, z, _) in enumerate(POINTS))
        data += struct.pack(order + "Biii", 3, 0, 1, 2)
        yield f"{name}.ply", head.format(name).encode() + data


TETRA = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def mesh_seeds():
    obj = "".join(f"v {x} {y} {z}\n" for x, y, z in TETRA)
    obj += "vn 0 0 1\nvt 0 0\n" + "".join(f"f {a+1}/1/1 {b+1}//1 {c+1}\n" for a, b, c in FACES)
    yield "mesh_obj", "tetra.obj", obj.encode()
    off = "OFF\n4 4 6\n" + "".join(f"{x} {y} {z}\n" for x, y, z in TETRA)
    off += "".join(f"3 {a} {b} {c}\n" for a, b, c in FACES)
    yield "mesh_off", "tetra.off", off.encode()
    ply = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n")
    ply += "".join(f"{x} {y} {z}\n" for x, y, z in TETRA)
    ply += "".join(f"3 {a} {b} {c}\n" for a, b, c in FACES)
    yield "mesh_ply", "tetra.ply", ply.encode()
    stl = "solid tetra\n"
    for face in FACES:
        stl += "facet normal 0 0 0\nouter loop\n"
        stl += "".join("vertex {} {} {}\n".format(*TETRA[v]) for v in face)
        stl += "endloop\nendfacet\n"
    yield "mesh_stl", "tetra_ascii.stl", (stl + "endsolid tetra\n").encode()
    binary = b"\0" * 80 + struct.pack("<I", len(FACES))
    for face in FACES:
        binary += struct.pack("<3f", 0, 0, 0)
        binary += b"".join(struct.pack("<3f", *TETRA[v]) for v in face) + b"\0\0"
    yield "mesh_stl", "tetra_binary.stl", binary


def other_seeds():
    yield "rig_text_edit", "styles.yaml", (
        "# every style a value is edited in (°)\nname: r\nmounts:\n"
        "  - id: front   # flow pose\n    sensor: \"cam\"\n    mode: 'a''b'\n"
        "    pose: {xyz: [0.20, 0, 0.3], rpy_deg: [0, 10, 0]}  # c\n"
        "  - id: rear\n    sensor: lidar\n    mode: m\n    pose:\n      xyz:\n"
        "        - -0.2    # behind\n        - 0.0\n        - 0.45\n"
        "      rpy_deg: [0, 0, 180]\n  - id: linked\n    sensor: s\n    mode: m\n"
        "    pose: {urdf_link: camera_link}\n").encode()
    # Issue 53: values shared through anchors, aliases and merge keys (each edit that would
    # change a sharer must be refused), in flow and block style, with tags and block scalars.
    yield "rig_text_edit", "aliases_flow.yaml", (
        "name: a\nmounts:\n"
        "  - {id: front, sensor: s, mode: &md m5, pose: &fp {xyz: [0.5, 0, 0.4], rpy_deg: [0, 0, 0]}}\n"
        "  - {id: rear, sensor: s, mode: m5, pose: {xyz: [-0.5, 0, 0.2], rpy_deg: [0, 0, 180]}}\n"
        "  - {id: third, sensor: s, mode: *md, pose: *fp}\n").encode()
    yield "rig_text_edit", "aliases_block.yaml", (
        "name: a\nmounts:\n  - id: front\n    sensor: s\n    mode: m\n    pose:\n"
        "      xyz: &v\n        - 0.5\n        - 0\n        - 0.4\n      rpy_deg: *v\n"
        "  - &whole\n    id: rear\n    sensor: s\n    mode: m\n"
        "    pose: {xyz: [0, 0, 1], rpy_deg: [0, 0, 0]}\n  - *whole\n").encode()
    yield "rig_text_edit", "merge_keys.yaml", (
        "defaults: &d {sensor: s, mode: m, pose: {xyz: [0, 0, 0.3], rpy_deg: [0, 0, 0]}}\n"
        "name: m\nmounts:\n  - id: front\n    <<: *d\n"
        "  - {id: rear, <<: [*d], pose: {xyz: [-0.2, 0, 0.3], rpy_deg: [0, 0, 180]}}\n"
        "  - id: side\n    sensor: s\n    mode: m\n    pose:\n      <<: {frame: body}\n"
        "      xyz: [0, 0.2, 0.3]\n      rpy_deg: [0, 0, 90]\n").encode()
    yield "rig_text_edit", "tags_and_blocks.yaml", (
        "name: t\nmounts:\n  - id: front\n    sensor: !!str s\n    mode: |\n      m5\n"
        "    pose: !!map {xyz: [!!float 0.5, &z 0, 0.4], rpy_deg: [0, *z, 0]}\n"
        "  - id: rear\n    sensor: >-\n      folded\n      name\n    mode: \"m\\u0035\"\n"
        "    pose: {xyz: [-0.5,\n        0, 0.2], rpy_deg: [0, 0, 180]}\n"
        "  - {id: flow, sensor: 's', mode: \"m\", pose: {xyz: [1, 2, 3], rpy_deg: [0, 0, 0]}}\n"
        ).encode()
    yield "map_pgm", "map.pgm", b"P5\n# seed\n4 3\n255\n" + bytes([254, 0, 205, 254] * 3)
    yield "rssi_csv", "rssi.csv", (
        "t,x,y,z,bssid,rssi\n" + "".join(
            f"{i},{0.1 * i},{-0.05 * i},0.4,02:00:00:00:00:01,{-60 - i}\n" for i in range(10))
    ).encode()
    yield "co2_csv", "co2.txt", "".join(
        f"{50 + 0.3 * i} {0.8 - 0.2 * i} {499 - i}.0\n" for i in range(10)).encode()
    yield "rssi_csv", "rssi_unheard.csv", (
        "# floor_dbm: -95\n# scan_period_s: 1\nt,x,y,z,bssid,rssi\n" + "".join(
            f"{i},{0.1 * i},0,0.4,02:00:00:00:00:01,{'' if i % 3 else -90 - i}\n"
            for i in range(10))
    ).encode()
    yield "emitter_truth_csv", "truth.csv", b"bssid,x,y,z\n02:00:00:00:00:01,3.5,-2,1.2\n"
    yield "walls_csv", "walls.csv", (
        b"x1,y1,x2,y2,attenuation_db\n-3,2,-0.5,2,8\n-0.5,2,0.5,2,3\n0.5,2,3,2,8\n")
    yield "artifacts_json", "artifacts.json", (
        b'{"artifacts": [{"id": 1, "type": "gas", "x": 14.3, "y": 43.5, "z": 2.0},'
        b' {"id": 2, "type": "vent", "x": -10.4, "y": 53.0, "z": 2.9}]}\n')
    yield "clearpath_robot_yaml", "robot.yaml", (
        b"serial_number: j100-0000\nversion: 0\nsystem: {ros2: {namespace: j100_0000}}\n"
        b"sensors:\n  lidar2d:\n    - {model: hokuyo_ust, parent: base_link, xyz: [0.19, 0.0, 0.1],"
        b" rpy: [0.0, 0.0, 0.0]}\n  lidar3d:\n    - model: velodyne_lidar\n      parent: base_link\n"
        b"      ros_parameters: {velodyne_driver_node: {model: 32C}}\n  camera:\n"
        b"    - {model: intel_realsense, ros_parameters: {intel_realsense: {device_type: d415}}}\n"
        b"    - {model: flir_blackfly}\n  imu:\n    - {model: microstrain_imu}\n")
    yield "collision_monitor_yaml", "circle.yaml", (
        b"collision_monitor:\n  ros__parameters:\n    base_frame_id: base_footprint\n"
        b"    polygons: [\"near\", \"wide\"]\n"
        b"    near: {type: circle, radius: 0.4, action_type: stop, sources_names: [\"scan\"]}\n"
        b"    wide: {type: polygon, points: [0.3, 0.3, 0.3, -0.3, 0.0, -0.3, 0.0, 0.3],"
        b" action_type: slowdown, max_points: 3}\n"
        b"    observation_sources: [\"scan\"]\n"
        b"    scan: {type: scan, topic: /front_lidar/scan, enabled: true}\n")
    yield "costmap_params_yaml", "stvl.yaml", (
        b"local_costmap:\n  local_costmap:\n    ros__parameters:\n"
        b"      plugins: [\"stvl_layer\"]\n      stvl_layer:\n"
        b"        plugin: \"spatio_temporal_voxel_layer/SpatioTemporalVoxelLayer\"\n"
        b"        decay_model: 0\n        voxel_decay: 5.4\n        observation_sources: lidar\n"
        b"        lidar: {obstacle_range: 3.0, min_z: 0.1, max_z: 3.5, filter: passthrough,"
        b" min_obstacle_height: 0.05, max_obstacle_height: 1.2, model_type: 1}\n")
    yield "scenario_yaml", "goals.scenario.yaml", (
        b"name: goals\nscene: lab.yaml\nstart: {xy: [0, 0], yaw_deg: 90}\n"
        b"route:\n  - {name: a, xy: [1, 2], wait: 1}\n"
        b"drops:\n  - {name: well, low: [2, -1], high: [3, 1]}\n"
        b"skip_unreachable: true\nmax_duration: 60\n"
        b"sensing: {min_obstacle_height: 0.04, negative_obstacles: true, lidar_decimation: 1}\n")
    yield "pipeline_yaml", "pipeline.yaml", (
        b"name: mine\nstages:\n  - voxel_grid: {leaf: 0.05}\n  - statistical_outlier\n"
        b"  - floor_removal_2: {ransac: {max_tilt_deg: 10}}\n")
    yield "filtering_loads_yaml", "loads.yaml", (
        b'machine: "seed"\npipeline: "P2"\nsensors:\n'
        b"  - {sensor: azure_kinect_dk, seconds_per_point: 1.0e-8}\n")
    yield "robot_urdf", "box.urdf", (
        b'<?xml version="1.0"?>\n<robot name="r">\n <link name="base_footprint"/>\n'
        b' <link name="base_link"><collision><origin xyz="0 0 0.1"/><geometry>'
        b'<box size="0.4 0.3 0.2"/></geometry></collision></link>\n'
        b' <joint name="j" type="fixed"><parent link="base_footprint"/><child link="base_link"/>'
        b'<origin xyz="0 0 0.05" rpy="0 0 1.5708"/></joint>\n</robot>\n')
    yield "robot_xacro", "box.urdf.xacro", (
        b'<?xml version="1.0"?>\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        b' <xacro:property name="h" value="0.2"/>\n <xacro:arg name="tall" default="false"/>\n'
        b' <xacro:macro name="box" params="name z:=0 *origin">\n'
        b'  <link name="${name}"><collision><xacro:insert_block name="origin"/><geometry>'
        b'<box size="0.4 0.3 ${h * 2 if z > 0 else h}"/></geometry></collision></link>\n'
        b' </xacro:macro>\n <link name="base_footprint"/>\n'
        b' <xacro:box name="base_link" z="1"><origin xyz="0 0 ${radians(90) / pi}"/></xacro:box>\n'
        b' <xacro:if value="$(arg tall)"><link name="tower"/></xacro:if>\n'
        b' <joint name="j" type="fixed"><parent link="base_footprint"/><child link="base_link"/>'
        b'</joint>\n</robot>\n')
    # Descriptions near the expansion limits (reliability reproducers 01, 03, 04): small
    # inputs whose expansion is large, so the fuzzer mutates around the bounds.
    head = b'<?xml version="1.0"?>\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
    yield "robot_xacro", "self_block.urdf.xacro", (
        head + b' <xacro:property name="b"><xacro:insert_block name="b"/></xacro:property>\n'
        b' <link name="base_link"/>\n <xacro:insert_block name="b"/>\n</robot>\n')
    doubling = b''.join(b' <xacro:property name="p%d" value="${p%d}${p%d}"/>\n' % (k, k - 1, k - 1)
                        for k in range(1, 24))
    yield "robot_xacro", "doubling.urdf.xacro", (
        head + b' <xacro:property name="p0" value="aaaaaaaaaaaaaaaa"/>\n' + doubling +
        b' <link name="base_link"><visual><material name="${p23}"/></visual></link>\n</robot>\n')
    macros = b''.join(b' <xacro:macro name="m%d" params=""><xacro:m%d/><xacro:m%d/></xacro:macro>\n'
                      % (k, k - 1, k - 1) for k in range(1, 20))
    yield "robot_xacro", "macro_doubling.urdf.xacro", (
        head + b' <xacro:macro name="m0" params=""><link name="x"/></xacro:macro>\n' + macros +
        b' <link name="base_link"/>\n <xacro:m19/>\n</robot>\n')


def main():
    out = sys.argv[1]
    seeds = [("cloud_pcd",) + s for s in pcd_seeds()] + [("cloud_ply",) + s for s in ply_seeds()]
    seeds += list(mesh_seeds()) + list(other_seeds())
    for target, name, data in seeds:
        os.makedirs(os.path.join(out, target), exist_ok=True)
        with open(os.path.join(out, target, name), "wb") as f:
            f.write(data)
    print(f"make_seeds: {len(seeds)} seeds in {out}")


if __name__ == "__main__":
    main()
