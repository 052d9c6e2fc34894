#pragma once
/// The largest coordinate magnitude [m] any reader accepts in a cloud or a log. No map on
/// Earth needs more (UTM northings stay below 1e7 m); float spacing there is 8 m; and it
/// keeps squared distances finite in float and grid indices within 64-bit integers.
namespace rigdesign::model {

constexpr double kMaxCoordinate = 1e8;

}  // namespace rigdesign::model
