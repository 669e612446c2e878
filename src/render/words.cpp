#include "render/words.hpp"

#include <fmt/format.h>

namespace dragon::render {

namespace {

const Words english{
    "head (outlined)",
    "benches by speed",
    "head (bench 1)",
    "body",
    "tail",
    "touching benches",
    "path",
    "path in",
    "S-curve",
    "path out",
    "turning space",
    "speed (m/s)",
    "t = {:.3f} s   pitch = {:.3g} m",
    "overlap {:.3f} m (benches {} and {})",
    "bench {}",
    "bench 1 (head)",
    "first contact t = {:.6f} s: benches {} and {}",
    "t = {:.3f} s   pitch = {:.3g} m   past the first contact (benches {} and {}, t = {:.3f} s)",
    "t = {:.3f} s",
    "held",
    "Coiling in: pitch {:g} m, head {:g} m/s",
    "Turnaround: pitch {:g} m, head {:g} m/s",
    "first contact: bench {} touches bench {}, t = {:.6f} s",
    "head reaches the turning space (r = {:g} m), t = {:.6f} s",
    "past the first contact (bench {} touches bench {} at t = {:.6f} s): benches overlap",
    "end of the valid motion, t = {:.6f} s: {}",
    "handle {} can no longer follow handle {}: the path at handle {} turns square to their link, so its speed has "
    "no bound",
    "handle {} would jump to a nearer point: the path between handles {} and {} swings back out to their link's length",
    "{} over {} and {}",
    "{} against {}",
    "no value",
    "the contest's dragon",
    "cut short: the dragon cannot follow its path",
    "refused (the row's status says why)",
    "no answer in the range searched",
    "answer below the range searched",
    "answer above the range searched",
    "benches overlap at the start: the chain collides",
    "no row (another shard's)",
};

// The contest's terms: 板凳龙 (the bench dragon), 龙头 (head), 龙身 (body), 龙尾 (tail), 把手
// (handle), 螺距 (pitch), 调头空间 (turning space).
const Words chinese{
    "龙头（描边）",
    "板凳（按速度着色）",
    "龙头（第 1 节板凳）",
    "龙身",
    "龙尾",
    "相碰的板凳",
    "路径",
    "盘入螺线",
    "S 形调头曲线",
    "盘出螺线",
    "调头空间",
    "速度 (m/s)",
    "t = {:.3f} s   螺距 = {:.3g} m",
    "重叠 {:.3f} m（第 {} 与第 {} 节板凳）",
    "第 {} 节板凳",
    "第 1 节板凳（龙头）",
    "首次碰撞 t = {:.6f} s：第 {} 与第 {} 节板凳",
    "t = {:.3f} s   螺距 = {:.3g} m   已过首次碰撞（第 {} 与第 {} 节板凳，t = {:.3f} s）",
    "t = {:.3f} s",
    "定格",
    "盘入：螺距 {:g} m，龙头速度 {:g} m/s",
    "调头：螺距 {:g} m，龙头速度 {:g} m/s",
    "首次碰撞：第 {} 节板凳碰到第 {} 节，t = {:.6f} s",
    "龙头到达调头空间（半径 {:g} m），t = {:.6f} s",
    "已过首次碰撞（第 {} 节碰到第 {} 节，t = {:.6f} s）：板凳相互重叠",
    "有效运动结束，t = {:.6f} s：{}",
    "把手 {} 无法再跟随把手 {}：把手 {} 处的路径与两把手连线垂直，其速度无界",
    "把手 {} 将跳到更近的点：把手 {} 与 {} 之间的路径又弯回到连杆长度",
    "{}：随{}与{}的变化",
    "{}：随{}的变化",
    "无数值",
    "竞赛题的板凳龙",
    "中途截止：板凳龙无法沿路径继续前进",
    "不允许的取值（见该行的 status）",
    "搜索范围内无解",
    "答案低于搜索范围",
    "答案高于搜索范围",
    "开始时板凳已重叠：龙身相撞",
    "无此行（属于其他分片）",
};

}  // namespace

const Words& words(Language language) { return language == Language::zh ? chinese : english; }

std::string jam_words(Language language, int handle, bool root_vanishes) {
    const Words& w = words(language);
    return root_vanishes ? fmt::format(fmt::runtime(w.jam_vanishes), handle, handle - 1, handle)
                         : fmt::format(fmt::runtime(w.jam_nearer), handle, handle - 1, handle);
}

}  // namespace dragon::render
