// The built-in xacro expander and its expressions. Expected values of expressions are
// Python 3's (xacro evaluates ${...} with Python), computed with python3 and pasted here.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>

#include "rigdesign/io/robot/robot_description_loader.hpp"
#include "rigdesign/io/robot/xacro_expression.hpp"
#include "rigdesign/model/input_error.hpp"
#include "support/cli_runner.hpp"
#include "support/path_guard.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;
using Catch::Matchers::WithinAbs;
using io::xacro::Value;

namespace {

Value eval(const std::string& expression, const std::map<std::string, Value>& names = {}) {
  return io::xacro::evaluate(expression, [&](const std::string& name) -> std::optional<Value> {
    const auto it = names.find(name);
    if (it == names.end()) return std::nullopt;
    return it->second;
  });
}

std::string text(const std::string& expression, const std::map<std::string, Value>& names = {}) {
  return io::xacro::to_text(eval(expression, names));
}

std::string first_error_of(const std::function<void()>& run) {
  try {
    run();
  } catch (const model::InputError& error) {
    return error.diagnostics().front().message();
  }
  return "no error";
}

}  // namespace

TEST_CASE("xacro expressions evaluate as Python does") {
  const std::map<std::string, Value> create3 = {{"mass", Value::of_real(2.3)},
                                                {"radius", Value::of_real(0.164)},
                                                {"length", Value::of_real(0.06)},
                                                {"cm2m", Value::of_real(1 / 100.0)}};
  // Python: (1/12) * 2.3 * (3*0.164*0.164 + 0.06*0.06) == 0.016155199999999998
  CHECK(text("(1/12) * mass * (3*radius*radius + length*length)", create3) ==
        "0.016155199999999998");
  CHECK(text("-pi/2") == "-1.5707963267948966");
  CHECK(text("-2.5*cm2m + 1*cm2m + 6.42*cm2m", create3) == "0.04920000000000001");
  CHECK(text("80*(pi/180.0)") == "1.3962634015954636");
  CHECK(text("1/100.0*6.42") == "0.06420000000000001");
  CHECK(text("7//2") == "3");
  CHECK(text("-7//2") == "-4");
  CHECK(text("-7%3") == "2");
  CHECK(text("7.5//2") == "3.0");
  CHECK(text("-7.5%2") == "0.5");
  CHECK(text("2**10") == "1024");
  CHECK(text("-2**2") == "-4");
  CHECK(text("2**-1") == "0.5");
  CHECK(text("1e-9") == "1e-09");
  CHECK(text("1e16") == "1e+16");
  CHECK(text("123456789012345678.0") == "1.2345678901234568e+17");
  CHECK(text("0.0001") == "0.0001");
  CHECK(text("6.0") == "6.0");
  CHECK(text("1 if 0 else 2") == "2");
  CHECK(text("'a' + 'b'") == "ab");
  CHECK(text("0 or 'x'") == "x");
  CHECK(text("3 and 0") == "0");
  CHECK(text("round(2.5)") == "2");
  CHECK(text("round(3.5)") == "4");
  CHECK(text("floor(-1.5)") == "-2");
  CHECK(text("1 < 2 < 3") == "True");
  CHECK(text("1 < 3 < 2") == "False");
  CHECK(text("radians(180)") == "3.141592653589793");
  CHECK(text("'classic' == 'ignition'") == "False");
  CHECK(text("'x' != 1") == "True");
  CHECK(text("not ''") == "True");
}

TEST_CASE("xacro expression errors name the place") {
  const auto offset_of = [](const std::string& expression) -> std::size_t {
    try {
      eval(expression);
    } catch (const io::xacro::ExpressionError& error) {
      return error.offset();
    }
    return 999;
  };
  CHECK(offset_of("1 + width") == 4);  // name 'width' is not defined
  CHECK(offset_of("1 / 0") == 2);      // division by zero
  CHECK(offset_of("(1 + 2") == 6);     // expected ')'
  CHECK(offset_of("1 2") == 2);        // unexpected '2'
  CHECK(offset_of("") == 0);
  CHECK(offset_of("'a' - 1") == 4);
  CHECK(offset_of(std::string(500, '(') + "1" + std::string(500, ')')) < 500);  // too deep
  CHECK_THROWS_WITH(eval("foo(1)"), Catch::Contains("function 'foo'"));
  CHECK_THROWS_WITH(eval("sin(1, 2)"), Catch::Contains("sin() takes 1"));
}

TEST_CASE("literal text reads as xacro reads property values") {
  CHECK(io::xacro::parse_literal("0.262").kind == Value::Kind::real);
  CHECK(io::xacro::parse_literal("1").kind == Value::Kind::integer);
  CHECK(io::xacro::parse_literal("true").kind == Value::Kind::boolean);
  CHECK(io::xacro::parse_literal("front/scan").kind == Value::Kind::text);
  CHECK(io::xacro::parse_literal("0 0 0").kind == Value::Kind::text);
}

TEST_CASE("the expander: properties, macros with blocks, conditions, includes, arguments") {
  TempFolder folder;
  folder.write("pkg/package.xml", "<package><name>my_robot</name></package>");
  folder.write("pkg/urdf/parts.xacro", R"X(<robot xmlns:xacro="http://ros.org/wiki/xacro">
  <xacro:property name="leg" value="${height / 2}"/>
  <xacro:macro name="post" params="name x:=0.1 *origin **extra">
    <link name="${name}"><collision><geometry><box size="0.1 0.1 ${leg}"/></geometry></collision>
      <xacro:insert_block name="extra"/></link>
    <joint name="${name}_joint" type="fixed"><parent link="base_footprint"/><child link="${name}"/>
      <xacro:insert_block name="origin"/></joint>
  </xacro:macro>
</robot>)X");
  const std::string top = folder.write("pkg/urdf/robot.urdf.xacro",
                                       R"X(<robot name="r" xmlns:xacro="http://ros.org/wiki/xacro">
  <xacro:arg name="side" default="left"/>
  <xacro:property name="height" value="0.8"/>
  <xacro:include filename="$(find my_robot)/urdf/parts.xacro"/>
  <link name="base_footprint"/>
  <xacro:post name="post_$(arg side)">
    <origin xyz="0.3 ${-0.2 if '$(arg side)' == 'right' else 0.2} ${leg / 2}"/>
    <extra><visual><geometry><sphere radius="0.01"/></geometry></visual></extra>
  </xacro:post>
  <xacro:unless value="$(optenv WITH_MISSING_ACCESSORY 0)">
    <link name="no_accessory"/>
    <joint name="na" type="fixed"><parent link="base_footprint"/><child link="no_accessory"/></joint>
  </xacro:unless>
  <xacro:if value="$(optenv WITH_MISSING_ACCESSORY 0)">
    <xacro:include filename="$(find package_nobody_has)/urdf/accessory.xacro"/>
  </xacro:if>
  <gazebo><plugin filename="$(find gazebo_only_package)/lib.so"/></gazebo>
</robot>)X");
  io::RobotDescriptionRequest request;
  request.path = top;
  request.package_paths = {folder.path()};
  request.expander = io::RobotDescriptionRequest::Expander::builtin;
  SECTION("default arguments") {
    const model::RobotDescription robot = io::load_robot_description(request);
    // leg = height / 2 = 0.4; the post's origin: xyz 0.3, +0.2 (side left), leg / 2 = 0.2.
    const auto T = robot.T_base("base_footprint", "post_left");
    REQUIRE(T);
    CHECK(T->translation().isApprox(model::Vec3(0.3, 0.2, 0.2), 1e-15));
    REQUIRE(robot.collisions.size() == 1);
    CHECK_THAT(robot.collisions[0].size.z(), WithinAbs(0.4, 1e-15));
    CHECK(robot.T_root_link.count("no_accessory") == 1);
  }
  SECTION("arguments and environment given by the rig") {
    request.args = {{"side", "right"}};
    request.environment = {{"WITH_MISSING_ACCESSORY", "1"}};
    // The accessory's include is now opened, and its package does not exist.
    const std::string message = first_error_of([&] { io::load_robot_description(request); });
    CHECK(message.find("robot.urdf.xacro:15") != std::string::npos);
    CHECK(message.find("package 'package_nobody_has' not found") != std::string::npos);
    request.environment.clear();
    const model::RobotDescription robot = io::load_robot_description(request);
    CHECK(robot.T_base("base_footprint", "post_right")->translation().y() == -0.2);
  }
}

TEST_CASE("bad robot descriptions: exit 2, file and line, nothing written") {
  TempFolder folder;
  const auto rig_for = [&](const std::string& description) {
    return folder.write("rig.yaml", "name: r\nrobot: {description: " + description +
                                        "}\ndistance_of_interest: 2.0\nmounts:\n"
                                        "  - {id: m, sensor: rplidar_a1m8, mode: 10hz, "
                                        "pose: {urdf_link: base_footprint}}\n");
  };
  const auto check_fails = [&](const std::string& file, const std::string& where,
                               const std::string& what) {
    const std::string rig = rig_for(file);
    const int before = folder.entries();
    const CliResult result = run_cli({"coverage", rig, "--out", folder.path() + "/out"});
    const std::string said = result.out + result.err;
    INFO(said);
    CHECK(result.exit_code == 2);
    CHECK(said.find(where) != std::string::npos);
    CHECK(said.find(what) != std::string::npos);
    CHECK(folder.entries() == before);  // no output folder appeared
  };
  const std::string head = "<robot name=\"r\" xmlns:xacro=\"http://ros.org/wiki/xacro\">\n";
  SECTION("an undefined property") {
    folder.write("a.urdf.xacro",
                 head +
                     "<link name=\"base_footprint\">\n<collision><geometry>"
                     "<box size=\"${w} 1 1\"/></geometry></collision></link></robot>");
    check_fails("a.urdf.xacro", "a.urdf.xacro:3", "name 'w' is not defined");
  }
  SECTION("a missing package") {
    folder.write("b.urdf.xacro",
                 head + "\n<xacro:include filename=\"$(find nope_pkg)/x.xacro\"/></robot>");
    check_fails("b.urdf.xacro", "b.urdf.xacro:3", "package 'nope_pkg' not found");
  }
  SECTION("a missing mesh") {
    folder.write("c.urdf",
                 "<robot name=\"r\"><link name=\"base_footprint\">\n<collision><geometry>"
                 "<mesh filename=\"gone.stl\"/></geometry></collision></link></robot>");
    check_fails("c.urdf", "c.urdf:2", "gone.stl' does not exist");
  }
  SECTION("a mesh with no triangles") {
    folder.write("empty.stl", "solid empty\nendsolid empty\n");
    folder.write("d.urdf",
                 "<robot name=\"r\"><link name=\"base_footprint\">\n<collision><geometry>"
                 "<mesh filename=\"empty.stl\"/></geometry></collision></link></robot>");
    check_fails("d.urdf", "d.urdf:2", "empty.stl");
  }
  SECTION("a cycle of includes") {
    folder.write("e.urdf.xacro", head + "<xacro:include filename=\"f.xacro\"/></robot>");
    folder.write("f.xacro", head + "\n<xacro:include filename=\"e.urdf.xacro\"/></robot>");
    check_fails("e.urdf.xacro", "f.xacro:3", "include cycle");
  }
  // urdfdom would build these (its links own their children) and leak the cycle; the joint
  // tree check names the joint and its line instead.
  const auto joint = [](const std::string& name, const std::string& parent,
                        const std::string& child) {
    return "<joint name=\"" + name + "\" type=\"fixed\"><parent link=\"" + parent +
           "\"/><child link=\"" + child + "\"/></joint>\n";
  };
  const std::string links =
      "<robot name=\"r\">\n<link name=\"base_footprint\"/><link name=\"a\"/>"
      "<link name=\"b\"/>\n";
  SECTION("a joint whose child is its parent") {
    folder.write("g.urdf",
                 links + joint("j0", "base_footprint", "a") + joint("self", "b", "b") + "</robot>");
    check_fails("g.urdf", "g.urdf:4", "joint 'self'.child: is 'b', its own parent link");
  }
  SECTION("a link that is the child of two joints") {
    folder.write("h.urdf", links + joint("j0", "base_footprint", "a") +
                               joint("j1", "base_footprint", "b") + joint("j2", "a", "b") +
                               "</robot>");
    check_fails("h.urdf", "h.urdf:5", "link 'b' is already the child of joint 'j1' (line 4)");
  }
  SECTION("joints that close a loop") {
    folder.write("i.urdf", links + joint("ab", "a", "b") + joint("ba", "b", "a") + "</robot>");
    check_fails("i.urdf", "i.urdf:4", "joint 'ba'.parent: closes a loop");
  }
}

TEST_CASE("ROS's xacro is used when it is on PATH, with the rig's arguments and environment") {
  TempFolder folder;
  // A stand-in for ROS's xacro: prints a URDF whose link names carry the argument and the
  // environment variable it was given, so the test sees both arrive.
  const std::string script = folder.write(
      "bin/xacro",
      "#!/bin/sh\nfor a in \"$@\"; do case \"$a\" in side:=*) side=${a#side:=};; esac; done\n"
      "echo \"<robot name='r'><link name='base_footprint'/><link name='${side}_$MOUNT'/>"
      "<joint name='j' type='fixed'><parent link='base_footprint'/><child link='${side}_$MOUNT'/>"
      "<origin xyz='0 0 0.5'/></joint></robot>\"\n");
  std::filesystem::permissions(script, std::filesystem::perms::owner_all);
  const std::string description =
      folder.write("robot.urdf.xacro",
                   "<robot name=\"r\" xmlns:xacro=\"http://ros.org/wiki/xacro\">"
                   "<link name=\"base_footprint\"/></robot>");
  const PathGuard path_guard(folder.path() + "/bin");
  io::RobotDescriptionRequest request;
  request.path = description;
  request.args = {{"side", "left"}};
  request.environment = {{"MOUNT", "mast"}};
  const auto run = [&] { return io::load_robot_description(request); };
  const model::RobotDescription robot = run();
  REQUIRE(robot.T_root_link.count("left_mast") == 1);
  CHECK(robot.T_base("base_footprint", "left_mast").value().translation().z() == 0.5);
  SECTION("its failure is reported with its own message") {
    folder.write("bin/xacro",
                 "#!/bin/sh\necho 'undefined substitution argument gazebo' >&2\nexit 2\n");
    std::filesystem::permissions(script, std::filesystem::perms::owner_all);
    const std::string message = first_error_of([&] { run(); });
    CHECK(message.find("undefined substitution argument gazebo") != std::string::npos);
  }
  SECTION("expander: builtin ignores it") {
    request.expander = io::RobotDescriptionRequest::Expander::builtin;
    CHECK(run().T_root_link.size() == 1);  // the file's own link, not the stand-in's two
  }
}
