<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="vi">
<context>
    <name>CommandsDialog</name>
    <message>
        <source>Custom commands</source>
        <translation>Lệnh tự định nghĩa</translation>
    </message>
    <message>
        <source>Ask before running</source>
        <translation>Hỏi trước khi chạy</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Tên</translation>
    </message>
    <message>
        <source>G-code lines</source>
        <translation>Các dòng G-code</translation>
    </message>
    <message>
        <source>or a G-code file</source>
        <translation>hoặc một file G-code</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Thêm</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Xóa</translation>
    </message>
    <message>
        <source>At most %1 commands</source>
        <translation>Tối đa %1 lệnh</translation>
    </message>
    <message>
        <source>New command</source>
        <translation>Lệnh mới</translation>
    </message>
    <message>
        <source>Command %1 (%2): %3</source>
        <translation>Lệnh %1 (%2): %3</translation>
    </message>
</context>
<context>
    <name>ConnectionBar</name>
    <message>
        <source>Port</source>
        <translation>Cổng</translation>
    </message>
    <message>
        <source>Baud</source>
        <translation>Baud</translation>
    </message>
    <message>
        <source>Machine:</source>
        <translation>Máy:</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Giao thức</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Ngắt kết nối</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Kết nối</translation>
    </message>
    <message>
        <source>link %1</source>
        <translation>liên kết: %1</translation>
    </message>
</context>
<context>
    <name>ConsoleView</name>
    <message>
        <source>filter (text)</source>
        <translation>lọc (chữ)</translation>
    </message>
    <message>
        <source>frames sent to the machine</source>
        <translation>khung gửi xuống máy</translation>
    </message>
    <message>
        <source>frames received from the machine</source>
        <translation>khung nhận từ máy</translation>
    </message>
    <message>
        <source>stream/status frames</source>
        <translation>khung dữ liệu/trạng thái</translation>
    </message>
    <message>
        <source>pause scrolling</source>
        <translation>dừng cuộn</translation>
    </message>
    <message>
        <source>MDI: a G-code line (G0 X10) or a command (HOME, SD LIST, GET KP_X)</source>
        <translation>MDI: một dòng G-code (G0 X10) hoặc một lệnh (HOME, SD LIST, GET KP_X)</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Gửi</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Xóa</translation>
    </message>
    <message>
        <source>resends %1 (%2 %)</source>
        <translation>gửi lại %1 (%2 %)</translation>
    </message>
</context>
<context>
    <name>CoverBanner</name>
    <message>
        <source>COVER OPEN - close to continue: no motion, spindle stopped. Resume restarts the spindle, then the job.</source>
        <translation>NẮP CHE ĐANG MỞ - đóng nắp để tiếp tục: không chuyển động, trục chính đã dừng. Tiếp tục sẽ bật lại trục chính rồi chạy tiếp chương trình.</translation>
    </message>
    <message>
        <source>Cover</source>
        <translation>Nắp che</translation>
    </message>
    <message>
        <source>COVER OPEN - close to continue</source>
        <translation>NẮP CHE ĐANG MỞ - đóng nắp để tiếp tục</translation>
    </message>
    <message>
        <source>Cover closed: press Resume to go on</source>
        <translation>Nắp che đã đóng: nhấn Tiếp tục để chạy tiếp</translation>
    </message>
    <message>
        <source>Cover closed</source>
        <translation>Nắp che đã đóng</translation>
    </message>
</context>
<context>
    <name>CustomBar</name>
    <message>
        <source>Commands…</source>
        <translation>Lệnh…</translation>
    </message>
    <message>
        <source>Add, change or remove your own command buttons</source>
        <translation>Thêm, sửa hoặc xóa các nút lệnh của bạn</translation>
    </message>
    <message>
        <source>file %1</source>
        <translation>file %1</translation>
    </message>
    <message>
        <source>Runs: %1</source>
        <translation>Chạy: %1</translation>
    </message>
    <message>
        <source>Asks first</source>
        <translation>Hỏi trước</translation>
    </message>
</context>
<context>
    <name>CustomCommands</name>
    <message>
        <source>Custom commands</source>
        <translation>Lệnh tự định nghĩa</translation>
    </message>
    <message>
        <source>Run “%1” now?</source>
        <translation>Chạy “%1” ngay bây giờ?</translation>
    </message>
    <message>
        <source>%1: the file %2 cannot be read (%3)</source>
        <translation>%1: không đọc được file %2 (%3)</translation>
    </message>
    <message>
        <source>%1 cannot be written (%2)</source>
        <translation>Không ghi được %1 (%2)</translation>
    </message>
</context>
<context>
    <name>DiagnosticsView</name>
    <message>
        <source>%1 error mm</source>
        <translation>lệch %1 mm</translation>
    </message>
</context>
<context>
    <name>Drivers</name>
    <message>
        <source>Auto</source>
        <translation>Tự động</translation>
    </message>
    <message>
        <source>This mill</source>
        <translation>Máy này</translation>
    </message>
    <message>
        <source>GRBL</source>
        <translation>GRBL</translation>
    </message>
</context>
<context>
    <name>Dro</name>
    <message>
        <source>The work offset is not known yet: connect to the machine first.</source>
        <translation>Chưa biết gốc phôi: hãy kết nối với máy trước.</translation>
    </message>
    <message>
        <source>Go to</source>
        <translation>Đi tới</translation>
    </message>
</context>
<context>
    <name>DroPanel</name>
    <message>
        <source>Position</source>
        <translation>Vị trí</translation>
    </message>
    <message>
        <source>Coordinate system</source>
        <translation>Hệ tọa độ</translation>
    </message>
    <message>
        <source>Work</source>
        <translation>Phôi</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Máy</translation>
    </message>
    <message>
        <source>Zero %1</source>
        <translation>Đặt 0 %1</translation>
    </message>
    <message>
        <source>Make the current position the work zero of %1 in the active system</source>
        <translation>Lấy vị trí hiện tại làm gốc phôi của trục %1 trong hệ tọa độ đang dùng</translation>
    </message>
    <message>
        <source>Work offsets (machine position of each work zero, mm)</source>
        <translation>Gốc phôi (vị trí máy của mỗi gốc phôi, mm)</translation>
    </message>
    <message>
        <source>Go to (work mm; an empty axis stays)</source>
        <translation>Đi tới (mm theo phôi; trục để trống giữ nguyên)</translation>
    </message>
    <message>
        <source>Go</source>
        <translation>Đi</translation>
    </message>
    <message>
        <source>Go to work zero</source>
        <translation>Về gốc phôi</translation>
    </message>
    <message>
        <source>Rapid to the top of Z first, then across, then down</source>
        <translation>Chạy nhanh lên đỉnh hành trình Z trước, rồi đi ngang, rồi hạ xuống</translation>
    </message>
    <message>
        <source>G92 in force: %1</source>
        <translation>G92 đang có hiệu lực: %1</translation>
    </message>
    <message>
        <source>Work offset %1 %2: “%3” is not a number</source>
        <translation>Gốc phôi %1 %2: “%3” không phải là số</translation>
    </message>
    <message>
        <source>Go to %1: “%2” is not a number</source>
        <translation>Đi tới %1: “%2” không phải là số</translation>
    </message>
</context>
<context>
    <name>FeatureDialog</name>
    <message>
        <source>Machining features</source>
        <translation>Gia công theo đặc trưng hình học</translation>
    </message>
    <message>
        <source>Job (in order)</source>
        <translation>Chương trình (theo thứ tự)</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Thêm</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Xóa</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>Lên</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>Xuống</translation>
    </message>
    <message>
        <source>Contour file</source>
        <translation>File biên dạng</translation>
    </message>
    <message>
        <source>Open a contour</source>
        <translation>Mở biên dạng</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Phía</translation>
    </message>
    <message>
        <source>outside (island)</source>
        <translation>bên ngoài (đảo)</translation>
    </message>
    <message>
        <source>inside (pocket)</source>
        <translation>bên trong (hốc)</translation>
    </message>
    <message>
        <source>Climb milling (else conventional)</source>
        <translation>Phay thuận (tắt: phay nghịch)</translation>
    </message>
    <message>
        <source>Geometry</source>
        <translation>Hình học</translation>
    </message>
    <message>
        <source>Tool and cutting</source>
        <translation>Dao và chế độ cắt</translation>
    </message>
    <message>
        <source>Open as program</source>
        <translation>Mở như chương trình</translation>
    </message>
    <message>
        <source>plain G-code</source>
        <translation>G-code thường</translation>
    </message>
    <message>
        <source>Fanuc 21 macro</source>
        <translation>Macro Fanuc 21</translation>
    </message>
    <message>
        <source>Fanuc 31 macro</source>
        <translation>Macro Fanuc 31</translation>
    </message>
    <message>
        <source>Save as…</source>
        <translation>Lưu thành…</translation>
    </message>
    <message>
        <source>Save in</source>
        <translation>Lưu dạng</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Đóng</translation>
    </message>
    <message numerus="yes">
        <source>Estimated time: %1 min %2 s, %n line(s)</source>
        <translation>
            <numerusform>Thời gian ước tính: %1 phút %2 giây, %n dòng</numerusform>
        </translation>
    </message>
    <message>
        <source>Fix the marked field to see the job.</source>
        <translation>Sửa ô được đánh dấu để xem chương trình.</translation>
    </message>
    <message>
        <source>Feature %1 (%2): %3</source>
        <translation>Đặc trưng %1 (%2): %3</translation>
    </message>
    <message>
        <source>Save the program</source>
        <translation>Lưu chương trình</translation>
    </message>
    <message>
        <source>G-code (*.nc *.ngc *.gcode)</source>
        <translation>G-code (*.nc *.ngc *.gcode)</translation>
    </message>
</context>
<context>
    <name>FeatureForm</name>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Rectangular pocket</source>
        <translation>Hốc chữ nhật</translation>
    </message>
    <message>
        <source>Round pocket</source>
        <translation>Hốc tròn</translation>
    </message>
    <message>
        <source>Slot</source>
        <translation>Rãnh</translation>
    </message>
    <message>
        <source>Face</source>
        <translation>Phay mặt</translation>
    </message>
    <message>
        <source>Profile (island or pocket from a contour)</source>
        <translation>Biên dạng (đảo hoặc hốc từ file biên dạng)</translation>
    </message>
    <message>
        <source>Holes on a circle</source>
        <translation>Lỗ trên vòng tròn</translation>
    </message>
    <message>
        <source>Holes in a row</source>
        <translation>Lỗ theo hàng</translation>
    </message>
    <message>
        <source>Peck depth (0: none)</source>
        <translation>Chiều sâu mỗi lần khoan (0: không)</translation>
    </message>
    <message>
        <source>Dwell at the bottom</source>
        <translation>Dừng ở đáy lỗ</translation>
    </message>
    <message>
        <source>X (lower left)</source>
        <translation>X (góc dưới trái)</translation>
    </message>
    <message>
        <source>Y (lower left)</source>
        <translation>Y (góc dưới trái)</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Chiều rộng</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Chiều cao</translation>
    </message>
    <message>
        <source>Corner radius</source>
        <translation>Bán kính góc</translation>
    </message>
    <message>
        <source>Angle about X+</source>
        <translation>Góc so với X+</translation>
    </message>
    <message>
        <source>X (centre)</source>
        <translation>X (tâm)</translation>
    </message>
    <message>
        <source>Y (centre)</source>
        <translation>Y (tâm)</translation>
    </message>
    <message>
        <source>Diameter</source>
        <translation>Đường kính</translation>
    </message>
    <message>
        <source>X start</source>
        <translation>X đầu</translation>
    </message>
    <message>
        <source>Y start</source>
        <translation>Y đầu</translation>
    </message>
    <message>
        <source>X end</source>
        <translation>X cuối</translation>
    </message>
    <message>
        <source>Y end</source>
        <translation>Y cuối</translation>
    </message>
    <message>
        <source>Stock around an island (M)</source>
        <translation>Lượng phôi quanh đảo (M)</translation>
    </message>
    <message>
        <source>Circle diameter</source>
        <translation>Đường kính vòng tròn</translation>
    </message>
    <message>
        <source>Holes</source>
        <translation>Số lỗ</translation>
    </message>
    <message>
        <source>Start angle</source>
        <translation>Góc bắt đầu</translation>
    </message>
    <message>
        <source>X (first hole)</source>
        <translation>X (lỗ đầu tiên)</translation>
    </message>
    <message>
        <source>Y (first hole)</source>
        <translation>Y (lỗ đầu tiên)</translation>
    </message>
    <message>
        <source>Pitch</source>
        <translation>Bước lỗ</translation>
    </message>
    <message>
        <source>Tool number</source>
        <translation>Số hiệu dao</translation>
    </message>
    <message>
        <source>Tool diameter (D)</source>
        <translation>Đường kính dao (D)</translation>
    </message>
    <message>
        <source>Stock top (Z)</source>
        <translation>Mặt trên phôi (Z)</translation>
    </message>
    <message>
        <source>Depth below the top (H)</source>
        <translation>Chiều sâu từ mặt trên (H)</translation>
    </message>
    <message>
        <source>Depth per layer (C)</source>
        <translation>Chiều sâu mỗi lớp (C)</translation>
    </message>
    <message>
        <source>Stepover (B)</source>
        <translation>Bước ngang (B)</translation>
    </message>
    <message>
        <source>Finishing allowance XY (U)</source>
        <translation>Lượng dư tinh XY (U)</translation>
    </message>
    <message>
        <source>Finishing allowance Z (W)</source>
        <translation>Lượng dư tinh Z (W)</translation>
    </message>
    <message>
        <source>Clearance (R)</source>
        <translation>Độ cao an toàn (R)</translation>
    </message>
    <message>
        <source>Feed (F)</source>
        <translation>Tốc độ chạy dao (F)</translation>
    </message>
    <message>
        <source>Plunge feed</source>
        <translation>Tốc độ ăn dao xuống</translation>
    </message>
    <message>
        <source>Spindle speed (S)</source>
        <translation>Tốc độ trục chính (S)</translation>
    </message>
    <message>
        <source>mm/min</source>
        <translation>mm/phút</translation>
    </message>
    <message>
        <source>rpm</source>
        <translation>vòng/phút</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Chọn…</translation>
    </message>
</context>
<context>
    <name>GrblAlarmBar</name>
    <message>
        <source>Reset</source>
        <translation>Đặt lại (reset)</translation>
    </message>
    <message>
        <source>Home ($H)</source>
        <translation>Về gốc ($H)</translation>
    </message>
    <message>
        <source>Unlock ($X)</source>
        <translation>Mở khóa ($X)</translation>
    </message>
    <message>
        <source>Lets the machine move without homing: it may not know where it is</source>
        <translation>Cho máy chuyển động mà không về gốc: máy có thể không biết mình đang ở đâu</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Báo động</translation>
    </message>
    <message>
        <source>MACHINE LOCKED (alarm): %1</source>
        <translation>MÁY ĐANG KHÓA (báo động): %1</translation>
    </message>
    <message>
        <source>Machine locked: %1</source>
        <translation>Máy đang khóa: %1</translation>
    </message>
</context>
<context>
    <name>GrblSettingsDialog</name>
    <message>
        <source>Machine settings ($$)</source>
        <translation>Cài đặt của máy ($$)</translation>
    </message>
    <message>
        <source>Setting</source>
        <translation>Cài đặt</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Giá trị</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Đơn vị</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Tên</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Ý nghĩa</translation>
    </message>
    <message>
        <source>Read again</source>
        <translation>Đọc lại</translation>
    </message>
    <message>
        <source>Back up to a file…</source>
        <translation>Sao lưu ra tệp…</translation>
    </message>
    <message>
        <source>Restore from a file…</source>
        <translation>Khôi phục từ tệp…</translation>
    </message>
    <message>
        <source>Send changes</source>
        <translation>Gửi các thay đổi</translation>
    </message>
    <message>
        <source>Discard changes</source>
        <translation>Bỏ các thay đổi</translation>
    </message>
    <message>
        <source>Changes to send (one at a time, each waited for):</source>
        <translation>Các thay đổi sẽ gửi (từng cái một, chờ máy trả lời từng cái):</translation>
    </message>
    <message>
        <source>$%1: “%2” is not a number; nothing changed</source>
        <translation>$%1: “%2” không phải là số; không có gì thay đổi</translation>
    </message>
    <message>
        <source>The machine has not sent its settings yet: nothing to back up.</source>
        <translation>Máy chưa gửi các cài đặt của nó: chưa có gì để sao lưu.</translation>
    </message>
    <message>
        <source>Back up the machine&apos;s settings</source>
        <translation>Sao lưu cài đặt của máy</translation>
    </message>
    <message>
        <source>Settings (*.txt);;All files (*)</source>
        <translation>Cài đặt (*.txt);;Mọi file (*)</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Không ghi được %1: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n setting(s) backed up to %1</source>
        <translation>
            <numerusform>Đã sao lưu %n cài đặt vào %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore the machine&apos;s settings</source>
        <translation>Khôi phục cài đặt của máy</translation>
    </message>
    <message>
        <source>no such file</source>
        <translation>không có tệp này</translation>
    </message>
    <message>
        <source>Backup not read, nothing changed: %1</source>
        <translation>Không đọc được bản sao lưu, không có gì thay đổi: %1</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n setting(s) differ from the machine&apos;s; check them, then Send changes.</source>
        <translation>
            <numerusform>%1: %n cài đặt khác với của máy; hãy kiểm tra, rồi nhấn Gửi các thay đổi.</numerusform>
        </translation>
    </message>
    <message>
        <source>Left out (this machine has no such setting): %1</source>
        <translation>Bỏ qua (máy này không có cài đặt đó): %1</translation>
    </message>
    <message>
        <source>Every change was written; the settings are read again.</source>
        <translation>Mọi thay đổi đã được ghi; đang đọc lại các cài đặt.</translation>
    </message>
    <message>
        <source>Writing $%1=%2 (%3 left)…</source>
        <translation>Đang ghi $%1=%2 (còn %3)…</translation>
    </message>
    <message>
        <source>$%1 was refused (%2); it and the changes after it were not written.</source>
        <translation>$%1 bị từ chối (%2); nó và các thay đổi sau nó chưa được ghi.</translation>
    </message>
</context>
<context>
    <name>GrblWindow</name>
    <message>
        <source>The work offsets could not be read (%1): the DRO shows none until they are read again, once the machine is at rest.</source>
        <translation>Không đọc được gốc phôi (%1): bảng tọa độ không hiện gốc phôi nào cho tới khi đọc lại được, lúc máy dừng yên.</translation>
    </message>
</context>
<context>
    <name>JobStatusBar</name>
    <message>
        <source>machine position in work coordinates (mm)</source>
        <translation>vị trí máy theo tọa độ phôi (mm)</translation>
    </message>
    <message>
        <source>no job</source>
        <translation>chưa chạy chương trình</translation>
    </message>
    <message>
        <source>line %1/%2 · elapsed %3 · remaining %4</source>
        <translation>dòng %1/%2 · đã chạy %3 · còn lại %4</translation>
    </message>
    <message>
        <source>line %1/%2 · elapsed %3 · remaining %4 · ends at %5</source>
        <translation>dòng %1/%2 · đã chạy %3 · còn lại %4 · xong lúc %5</translation>
    </message>
</context>
<context>
    <name>JogPanel</name>
    <message>
        <source>Jog</source>
        <translation>Chạy tay (jog)</translation>
    </message>
    <message>
        <source>Jog one axis by the chosen step at the feed beside it</source>
        <translation>Di chuyển từng trục theo bước đã chọn, với tốc độ chạy dao bên cạnh</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Giữ</translation>
    </message>
    <message>
        <source>Jog while a button is held (Alt+4); the arrow keys and PageUp/PageDown always do</source>
        <translation>Chạy tay khi giữ nút (Alt+4); các phím mũi tên và PageUp/PageDown luôn chạy như vậy</translation>
    </message>
    <message>
        <source> mm/min</source>
        <translation> mm/phút</translation>
    </message>
</context>
<context>
    <name>LinkAlert</name>
    <message>
        <source>The machine&apos;s internal link (UART between the main board and the motion board) is lost.</source>
        <translation>Mất liên kết bên trong máy (UART giữa bo mạch chính và bo điều khiển động cơ).</translation>
    </message>
    <message>
        <source>The serial port to the machine failed (cable unplugged, or the machine switched off); the details are in the console.</source>
        <translation>Cổng nối tiếp tới máy bị lỗi (rút cáp, hoặc máy đã tắt); chi tiết ở cửa sổ lệnh.</translation>
    </message>
    <message>
        <source>The machine has not answered for 3 s: no valid frame came over the link.</source>
        <translation>Máy không trả lời đã 3 giây: không có khung dữ liệu hợp lệ nào về qua đường truyền.</translation>
    </message>
    <message>
        <source>The machine has sent no status report for 3 s (a GRBL machine has no heartbeat: its reports are the sign of life).</source>
        <translation>Máy không gửi báo cáo trạng thái nào trong 3 s (máy GRBL không có nhịp tim: báo cáo trạng thái là dấu hiệu máy còn hoạt động).</translation>
    </message>
    <message>
        <source>Last state seen: %1.</source>
        <translation>Trạng thái thấy lần cuối: %1.</translation>
    </message>
    <message>
        <source>A job from the SD card carries on without this computer.</source>
        <translation>Chương trình chạy từ thẻ SD vẫn tiếp tục mà không cần máy tính này.</translation>
    </message>
    <message>
        <source>The main board holds the job: the motion board did not answer it.</source>
        <translation>Mạch chính giữ chương trình lại: mạch điều khiển chuyển động không trả lời.</translation>
    </message>
    <message>
        <source>A GRBL machine does not notice that this computer is gone: it runs the lines already in its buffer, then waits.</source>
        <translation>Máy GRBL không biết máy tính này đã mất kết nối: nó chạy hết các dòng đã có trong bộ đệm, rồi chờ.</translation>
    </message>
    <message>
        <source>If the machine is still powered, it holds the job on the path once it has missed this computer for 3 s; it keeps its place unless it was reset.</source>
        <translation>Nếu máy vẫn còn điện, máy sẽ dừng chương trình trên đường chạy dao sau 3 giây không nghe thấy máy tính này; máy giữ nguyên vị trí trừ khi đã bị khởi động lại.</translation>
    </message>
    <message>
        <source>No job was running.</source>
        <translation>Không có chương trình nào đang chạy.</translation>
    </message>
    <message>
        <source>Link lost</source>
        <translation>Mất kết nối</translation>
    </message>
    <message>
        <source>Reconnect</source>
        <translation>Kết nối lại</translation>
    </message>
    <message>
        <source>Resume job</source>
        <translation>Chạy tiếp</translation>
    </message>
    <message>
        <source>Home and restart</source>
        <translation>Về gốc và chạy lại</translation>
    </message>
    <message>
        <source>Abandon job</source>
        <translation>Hủy chương trình</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Đóng</translation>
    </message>
    <message>
        <source>⚠ Link to the machine lost</source>
        <translation>⚠ Mất kết nối với máy</translation>
    </message>
    <message>
        <source>Check the cable and the machine&apos;s power, then reconnect.</source>
        <translation>Kiểm tra cáp và nguồn điện của máy, rồi kết nối lại.</translation>
    </message>
    <message>
        <source>✓ Link restored</source>
        <translation>✓ Đã kết nối lại</translation>
    </message>
    <message>
        <source>The machine kept its position. Resume the job at line %1 of %2: no line runs twice, none is skipped.</source>
        <translation>Máy vẫn giữ vị trí. Chạy tiếp chương trình từ dòng %1 trên %2: không dòng nào chạy hai lần, không dòng nào bị bỏ qua.</translation>
    </message>
    <message>
        <source>The machine was reset and no longer knows its position. Home it, check the stock, then restart at line %1 of %2 with the feed and spindle restored.</source>
        <translation>Máy đã khởi động lại và không còn biết vị trí. Hãy cho máy về gốc, kiểm tra phôi, rồi chạy lại từ dòng %1 trên %2 với tốc độ chạy dao và trục chính như cũ.</translation>
    </message>
    <message>
        <source>GRBL cannot resume a job exactly. Start again at line %1 of %2, the line after the last one known finished (its “ok” came back and its motion was done), with the units, work system, coolant, spindle and feed restored; lines after it may already have run.</source>
        <translation>GRBL không thể tiếp tục công việc một cách chính xác. Chạy lại từ dòng %1 trên %2, dòng ngay sau dòng cuối cùng đã biết chắc là xong (đã nhận “ok” và chuyển động đã hoàn tất), với đơn vị, hệ tọa độ làm việc, dung dịch làm mát, trục chính và lượng chạy dao được khôi phục; các dòng sau đó có thể đã chạy.</translation>
    </message>
    <message>
        <source>The machine was reset and no longer knows its position: it is homed first.</source>
        <translation>Máy đã bị khởi động lại và không còn biết vị trí của nó: máy sẽ về gốc trước.</translation>
    </message>
    <message>
        <source>Start here at line %1</source>
        <translation>Chạy từ dòng %1</translation>
    </message>
    <message>
        <source>The machine answers again.</source>
        <translation>Máy đã trả lời trở lại.</translation>
    </message>
</context>
<context>
    <name>LinkState</name>
    <message>
        <source>connected</source>
        <translation>đã kết nối</translation>
    </message>
    <message>
        <source>degraded</source>
        <translation>chập chờn</translation>
    </message>
    <message>
        <source>lost</source>
        <translation>mất kết nối</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>chưa kết nối</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>đang kết nối</translation>
    </message>
</context>
<context>
    <name>LivePanel</name>
    <message>
        <source>Active G-codes</source>
        <translation>Mã G đang hiệu lực</translation>
    </message>
    <message>
        <source>Feed (programmed / actual)</source>
        <translation>Tốc độ tiến (lập trình / thực tế)</translation>
    </message>
    <message>
        <source>Spindle (commanded / measured)</source>
        <translation>Trục chính (lệnh / đo được)</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Dao</translation>
    </message>
    <message>
        <source>Source line</source>
        <translation>Dòng nguồn</translation>
    </message>
    <message>
        <source>Subprogram / loop pass</source>
        <translation>Chương trình con / lượt lặp</translation>
    </message>
    <message>
        <source>G92 offset</source>
        <translation>Độ dời G92</translation>
    </message>
    <message>
        <source>T%1</source>
        <translation>T%1</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>main program</source>
        <translation>chương trình chính</translation>
    </message>
    <message>
        <source>%1, pass %2</source>
        <translation>%1, lượt %2</translation>
    </message>
    <message>
        <source>not in force</source>
        <translation>không có hiệu lực</translation>
    </message>
</context>
<context>
    <name>Loader</name>
    <message>
        <source>the program could not be read from the machine&apos;s position: %1</source>
        <translation>không đọc được chương trình từ vị trí của máy: %1</translation>
    </message>
    <message>
        <source>%1 could not be loaded: %2</source>
        <translation>Không tải được %1: %2</translation>
    </message>
    <message>
        <source>%1 could not be read as G-code: %2</source>
        <translation>Không đọc được %1 như G-code: %2</translation>
    </message>
    <message>
        <source>%1 does not exist (moved or deleted?).</source>
        <translation>%1 không tồn tại (đã bị chuyển đi hoặc xóa?).</translation>
    </message>
    <message>
        <source>%1 cannot be opened: %2.</source>
        <translation>Không mở được %1: %2.</translation>
    </message>
    <message>
        <source>%1 is UTF-16 text: save it as UTF-8 (or plain ASCII) text.</source>
        <translation>%1 là văn bản UTF-16: hãy lưu lại dưới dạng văn bản UTF-8 (hoặc ASCII thuần).</translation>
    </message>
    <message>
        <source>%1 is not a G-code file (it holds binary data, such as an image).</source>
        <translation>%1 không phải file G-code (nó chứa dữ liệu nhị phân, ví dụ một hình ảnh).</translation>
    </message>
</context>
<context>
    <name>LoaderTexts</name>
    <message numerus="yes">
        <source>%1 does not look like G-code: nothing in it can be run (%n error(s); first, line %2: %3).</source>
        <translation>
            <numerusform>%1 không giống G-code: không có gì trong đó chạy được (%n lỗi; lỗi đầu tiên ở dòng %2: %3).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MachineCodes</name>
    <message>
        <source>a limit switch was hit</source>
        <translation>công tắc hành trình bị chạm</translation>
    </message>
    <message>
        <source>following error: an axis fell behind its path</source>
        <translation>sai lệch bám: một trục bị tụt lại so với quỹ đạo</translation>
    </message>
    <message>
        <source>the machine lost the computer link</source>
        <translation>máy mất kết nối với máy tính</translation>
    </message>
    <message>
        <source>the link between the machine&apos;s two boards is lost</source>
        <translation>mất liên kết giữa hai bo mạch của máy</translation>
    </message>
    <message>
        <source>the machine (re)started</source>
        <translation>máy vừa khởi động (lại)</translation>
    </message>
    <message>
        <source>the machine is not homed</source>
        <translation>máy chưa về gốc</translation>
    </message>
    <message>
        <source>the move would leave the travel (soft limit)</source>
        <translation>lệnh di chuyển sẽ vượt hành trình (giới hạn mềm)</translation>
    </message>
    <message>
        <source>the machine cannot read this line</source>
        <translation>máy không đọc được dòng này</translation>
    </message>
    <message>
        <source>a value is out of range</source>
        <translation>một giá trị nằm ngoài phạm vi</translation>
    </message>
    <message>
        <source>no feed rate (F) given</source>
        <translation>chưa có tốc độ chạy dao (F)</translation>
    </message>
    <message>
        <source>the arc is not valid</source>
        <translation>cung tròn không hợp lệ</translation>
    </message>
    <message>
        <source>the line number is out of order</source>
        <translation>số thứ tự dòng không đúng</translation>
    </message>
    <message>
        <source>the machine is busy</source>
        <translation>máy đang bận</translation>
    </message>
    <message>
        <source>the cover is open: no motion allowed</source>
        <translation>nắp che đang mở: không được phép chuyển động</translation>
    </message>
    <message>
        <source>the machine is in alarm: home it after a fault</source>
        <translation>máy đang báo lỗi: cho máy về gốc sau sự cố</translation>
    </message>
    <message>
        <source>the machine&apos;s queue is full</source>
        <translation>hàng đợi lệnh của máy đã đầy</translation>
    </message>
    <message>
        <source>wrong arguments for the command</source>
        <translation>sai tham số của lệnh</translation>
    </message>
    <message>
        <source>no such setting</source>
        <translation>không có thông số này</translation>
    </message>
    <message>
        <source>the machine does not know this command</source>
        <translation>máy không hiểu lệnh này</translation>
    </message>
    <message>
        <source>the file name is not allowed on the card</source>
        <translation>tên file không hợp lệ trên thẻ nhớ</translation>
    </message>
    <message>
        <source>no such file on the card</source>
        <translation>không có file này trên thẻ nhớ</translation>
    </message>
    <message>
        <source>the SD card is full</source>
        <translation>thẻ SD đã đầy</translation>
    </message>
    <message>
        <source>the file on the card does not match (CRC)</source>
        <translation>file trên thẻ nhớ không khớp (CRC)</translation>
    </message>
    <message>
        <source>axis %1 in the %2 direction: %3 mm is past the limit %4 mm</source>
        <translation>trục %1 theo chiều %2: %3 mm vượt quá giới hạn %4 mm</translation>
    </message>
</context>
<context>
    <name>MachineControls</name>
    <message>
        <source>Home</source>
        <translation>Về gốc máy</translation>
    </message>
    <message>
        <source>Home (recover)</source>
        <translation>Về gốc (sau sự cố)</translation>
    </message>
    <message>
        <source>after a fault: first move away from the switches, then home</source>
        <translation>sau sự cố: trước hết lùi ra khỏi công tắc hành trình, rồi về gốc máy</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Chạy</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Tạm dừng</translation>
    </message>
    <message>
        <source>feed hold, at once</source>
        <translation>dừng chạy dao ngay lập tức</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Tiếp tục</translation>
    </message>
    <message>
        <source>STOP</source>
        <translation>DỪNG</translation>
    </message>
    <message>
        <source>stop and flush, at once</source>
        <translation>dừng khẩn và xóa hàng đợi ngay lập tức</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Bật</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Tắt</translation>
    </message>
    <message>
        <source>Job</source>
        <translation>Chương trình</translation>
    </message>
    <message>
        <source>Check mode (dry run, no motion)</source>
        <translation>Chạy thử (không chuyển động)</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Trục chính</translation>
    </message>
    <message>
        <source> rpm</source>
        <translation> vòng/phút</translation>
    </message>
    <message>
        <source>Work zero (here)</source>
        <translation>Đặt gốc phôi (tại đây)</translation>
    </message>
    <message>
        <source>commanded %1 · measured %2 rpm</source>
        <translation>đặt %1 · đo được %2 vòng/phút</translation>
    </message>
    <message>
        <source>Optional stop (M01 holds the job)</source>
        <translation>Dừng tùy chọn (M01 dừng chương trình)</translation>
    </message>
    <message>
        <source>Override travel check (check mode only)</source>
        <translation>Bỏ qua kiểm tra hành trình (chỉ khi chạy thử)</translation>
    </message>
    <message>
        <source>run a program that leaves the travel as a dry run</source>
        <translation>chạy thử một chương trình vượt hành trình</translation>
    </message>
</context>
<context>
    <name>MachineFlags</name>
    <message>
        <source>homed</source>
        <translation>đã về gốc</translation>
    </message>
    <message>
        <source>cover open</source>
        <translation>nắp mở</translation>
    </message>
    <message>
        <source>host lost</source>
        <translation>mất máy tính</translation>
    </message>
    <message>
        <source>UART lost</source>
        <translation>mất UART</translation>
    </message>
    <message>
        <source>spindle</source>
        <translation>trục chính quay</translation>
    </message>
    <message>
        <source>SD</source>
        <translation>chạy từ SD</translation>
    </message>
</context>
<context>
    <name>MachinePanelView</name>
    <message>
        <source>Cover open</source>
        <translation>Nắp che mở</translation>
    </message>
    <message>
        <source>the cover switch: while open the machine refuses every motion</source>
        <translation>công tắc nắp che: khi nắp mở, máy từ chối mọi chuyển động</translation>
    </message>
    <message>
        <source>the machine&apos;s 128 x 64 OLED (its 5x7 font is ASCII only)</source>
        <translation>màn hình OLED 128 x 64 của máy (phông 5x7 chỉ có ký tự ASCII)</translation>
    </message>
    <message>
        <source>MRESET: resets the main board; RESET: the motion board</source>
        <translation>MRESET: khởi động lại bo mạch chính; RESET: bo điều khiển động cơ</translation>
    </message>
    <message>
        <source>no machine panel (connect to the built-in simulator)</source>
        <translation>không có bảng điều khiển máy (hãy kết nối với bộ mô phỏng có sẵn)</translation>
    </message>
    <message>
        <source>LED</source>
        <translation>Đèn LED</translation>
    </message>
    <message>
        <source>buzzer</source>
        <translation>còi</translation>
    </message>
    <message>
        <source>buzzer off</source>
        <translation>còi tắt</translation>
    </message>
</context>
<context>
    <name>MachineStart</name>
    <message>
        <source>Reading the program again from where the machine stands…</source>
        <translation>Đang đọc lại chương trình từ vị trí máy đang đứng…</translation>
    </message>
    <message>
        <source>Program not started</source>
        <translation>Chương trình chưa chạy</translation>
    </message>
</context>
<context>
    <name>MachineState</name>
    <message>
        <source>IDLE</source>
        <translation>CHỜ</translation>
    </message>
    <message>
        <source>HOMING</source>
        <translation>ĐANG VỀ GỐC</translation>
    </message>
    <message>
        <source>RUN</source>
        <translation>ĐANG CHẠY</translation>
    </message>
    <message>
        <source>HOLD</source>
        <translation>TẠM DỪNG</translation>
    </message>
    <message>
        <source>JOG</source>
        <translation>CHẠY TAY</translation>
    </message>
    <message>
        <source>ALARM</source>
        <translation>BÁO LỖI</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>Program</source>
        <translation>Chương trình</translation>
    </message>
    <message>
        <source>Machine controls</source>
        <translation>Điều khiển máy</translation>
    </message>
    <message>
        <source>SD card</source>
        <translation>Thẻ SD</translation>
    </message>
    <message>
        <source>Machine panel</source>
        <translation>Bảng điều khiển máy</translation>
    </message>
    <message>
        <source>Live position</source>
        <translation>Vị trí trực tiếp</translation>
    </message>
    <message>
        <source>Console</source>
        <translation>Bảng lệnh</translation>
    </message>
    <message>
        <source>Position and work offsets</source>
        <translation>Vị trí và gốc phôi</translation>
    </message>
    <message>
        <source>Live modal state</source>
        <translation>Trạng thái modal trực tiếp</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Cài đặt</translation>
    </message>
    <message>
        <source>Tool table</source>
        <translation>Bảng dao</translation>
    </message>
    <message>
        <source>CNC mill controller</source>
        <translation>Điều khiển máy phay CNC</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Kết nối</translation>
    </message>
    <message>
        <source>Custom commands</source>
        <translation>Lệnh tự định nghĩa</translation>
    </message>
    <message>
        <source>2-D view</source>
        <translation>Hình 2-D</translation>
    </message>
    <message>
        <source>3-D view</source>
        <translation>Hình 3-D</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Vị trí</translation>
    </message>
    <message>
        <source>Diagnostics (commanded vs measured)</source>
        <translation>Chẩn đoán (lệnh so với đo được)</translation>
    </message>
    <message>
        <source>Loading %1…</source>
        <translation>Đang tải %1…</translation>
    </message>
    <message>
        <source>Preferences not saved: %1</source>
        <translation>Chưa lưu được tùy chọn: %1</translation>
    </message>
    <message>
        <source>Window layout</source>
        <translation>Bố cục cửa sổ</translation>
    </message>
    <message>
        <source>Window layout not saved: %1</source>
        <translation>Chưa lưu được bố cục cửa sổ: %1</translation>
    </message>
</context>
<context>
    <name>Menus</name>
    <message>
        <source>G-code (*.ngc *.nc *.gcode *.gc *.tap *.cnc *.txt);;Point lists (*.xyz *.txt *.csv *.dat);;All files (*)</source>
        <translation>G-code (*.ngc *.nc *.gcode *.gc *.tap *.cnc *.txt);;Danh sách điểm (*.xyz *.txt *.csv *.dat);;Mọi file (*)</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Tệp</translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation>&amp;Máy</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Xem</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Trợ &amp;giúp</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Mở…</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>Mở &amp;gần đây</translation>
    </message>
    <message>
        <source>New from &amp;features…</source>
        <translation>Tạo mới từ &amp;đặc trưng hình học…</translation>
    </message>
    <message>
        <source>pockets, slots, islands, hole patterns</source>
        <translation>hốc, rãnh, đảo, mẫu lỗ</translation>
    </message>
    <message>
        <source>&amp;Reload</source>
        <translation>&amp;Tải lại</translation>
    </message>
    <message>
        <source>&amp;Block delete: skip lines starting with /</source>
        <translation>&amp;Xóa khối: bỏ qua các dòng bắt đầu bằng /</translation>
    </message>
    <message>
        <source>&amp;Save to SD card…</source>
        <translation>&amp;Lưu vào thẻ SD…</translation>
    </message>
    <message>
        <source>Save screens&amp;hot…</source>
        <translation>Lưu ả&amp;nh màn hình…</translation>
    </message>
    <message>
        <source>Se&amp;ttings…</source>
        <translation>&amp;Cài đặt…</translation>
    </message>
    <message>
        <source>Tool ta&amp;ble…</source>
        <translation>&amp;Bảng dao…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Thoát</translation>
    </message>
    <message>
        <source>&amp;Connect / disconnect</source>
        <translation>&amp;Kết nối / ngắt kết nối</translation>
    </message>
    <message>
        <source>&amp;Home</source>
        <translation>&amp;Về gốc máy</translation>
    </message>
    <message>
        <source>Home after a &amp;fault</source>
        <translation>Về gốc sau &amp;sự cố</translation>
    </message>
    <message>
        <source>&amp;Start job</source>
        <translation>&amp;Chạy chương trình</translation>
    </message>
    <message>
        <source>&amp;Pause (feed hold)</source>
        <translation>&amp;Tạm dừng (dừng chạy dao)</translation>
    </message>
    <message>
        <source>R&amp;esume</source>
        <translation>Tiếp t&amp;ục</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>&amp;Dừng</translation>
    </message>
    <message>
        <source>stop and flush at once</source>
        <translation>dừng khẩn và xóa hàng đợi ngay lập tức</translation>
    </message>
    <message>
        <source>&amp;Jog</source>
        <translation>Chạy &amp;tay</translation>
    </message>
    <message>
        <source>Step 0.1 mm</source>
        <translation>Bước 0,1 mm</translation>
    </message>
    <message>
        <source>Step 1 mm</source>
        <translation>Bước 1 mm</translation>
    </message>
    <message>
        <source>Step 10 mm</source>
        <translation>Bước 10 mm</translation>
    </message>
    <message>
        <source>Hold to jog</source>
        <translation>Giữ để chạy tay</translation>
    </message>
    <message>
        <source>Spindle o&amp;n</source>
        <translation>&amp;Bật trục chính</translation>
    </message>
    <message>
        <source>Spindle o&amp;ff</source>
        <translation>Tắ&amp;t trục chính</translation>
    </message>
    <message>
        <source>Set work zero X&amp;Y here</source>
        <translation>Đặt gốc phôi X&amp;Y tại đây</translation>
    </message>
    <message>
        <source>Set work zero &amp;Z here</source>
        <translation>Đặt gốc phôi &amp;Z tại đây</translation>
    </message>
    <message>
        <source>Check mode (&amp;dry run)</source>
        <translation>Chạy t&amp;hử (không chuyển động)</translation>
    </message>
    <message>
        <source>&amp;Overrides</source>
        <translation>&amp;Điều chỉnh tốc độ</translation>
    </message>
    <message>
        <source>Feed +10 %</source>
        <translation>Tốc độ chạy dao +10 %</translation>
    </message>
    <message>
        <source>Feed −10 %</source>
        <translation>Tốc độ chạy dao −10 %</translation>
    </message>
    <message>
        <source>Feed +1 %</source>
        <translation>Tốc độ chạy dao +1 %</translation>
    </message>
    <message>
        <source>Feed −1 %</source>
        <translation>Tốc độ chạy dao −1 %</translation>
    </message>
    <message>
        <source>Feed 100 %</source>
        <translation>Tốc độ chạy dao 100 %</translation>
    </message>
    <message>
        <source>Spindle +10 %</source>
        <translation>Trục chính +10 %</translation>
    </message>
    <message>
        <source>Spindle −10 %</source>
        <translation>Trục chính −10 %</translation>
    </message>
    <message>
        <source>Spindle 100 %</source>
        <translation>Trục chính 100 %</translation>
    </message>
    <message>
        <source>Rapid 25 %</source>
        <translation>Chạy nhanh 25 %</translation>
    </message>
    <message>
        <source>Rapid 50 %</source>
        <translation>Chạy nhanh 50 %</translation>
    </message>
    <message>
        <source>Rapid 100 %</source>
        <translation>Chạy nhanh 100 %</translation>
    </message>
    <message>
        <source>&amp;Fit program</source>
        <translation>&amp;Vừa khung chương trình</translation>
    </message>
    <message>
        <source>Zoom &amp;in</source>
        <translation>Phóng &amp;to</translation>
    </message>
    <message>
        <source>Zoom &amp;out</source>
        <translation>Thu &amp;nhỏ</translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation>&amp;Lưới</translation>
    </message>
    <message>
        <source>&amp;Dark palette</source>
        <translation>Giao diện &amp;tối</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>&amp;Đặt lại bố cục</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Ngôn ngữ</translation>
    </message>
    <message>
        <source>Operator &amp;guide</source>
        <translation>&amp;Hướng dẫn sử dụng</translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>&amp;Giới thiệu</translation>
    </message>
    <message>
        <source>Open G-code</source>
        <translation>Mở file G-code</translation>
    </message>
    <message>
        <source>(none yet)</source>
        <translation>(chưa có)</translation>
    </message>
    <message>
        <source>Save screenshot</source>
        <translation>Lưu ảnh màn hình</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>Ảnh PNG (*.png)</translation>
    </message>
    <message>
        <source>Operator guide</source>
        <translation>Hướng dẫn sử dụng</translation>
    </message>
    <message>
        <source>About</source>
        <translation>Giới thiệu</translation>
    </message>
    <message>
        <source>&lt;b&gt;CNC mill controller&lt;/b&gt;&lt;br&gt;A desktop controller for a small 3-axis mill: G-code preview, SD upload, streaming over a checked frame protocol with resume after a link loss, and a simulator of the machine.&lt;br&gt;PySide6 + pyqtgraph. MIT licence.</source>
        <translation>&lt;b&gt;Điều khiển máy phay CNC&lt;/b&gt;&lt;br&gt;Phần mềm điều khiển máy phay CNC 3 trục cỡ nhỏ: xem trước G-code, lưu vào thẻ SD, gửi chương trình qua giao thức khung có kiểm tra, chạy tiếp sau khi mất kết nối, và bộ mô phỏng máy.&lt;br&gt;PySide6 + pyqtgraph. Giấy phép MIT.</translation>
    </message>
    <message>
        <source>1. Connect (the built-in simulator is first in the port list).
2. File ▸ Open (or drop a file on the window); check the preview and the Problems list.
3. Optionally save the program to the SD card (SD card dock).
4. Home (Ctrl+H), then Start (Ctrl+R). Pause Ctrl+P, Resume Ctrl+Shift+P, Stop Esc.
5. Jog with Ctrl+arrows (X/Y) and Ctrl+PgUp/PgDn (Z); step Alt+1/2/3.
If the link drops, the machine holds; reconnect and resume from the alert.</source>
        <translation>1. Kết nối (bộ mô phỏng có sẵn đứng đầu danh sách cổng).
2. Tệp ▸ Mở (hoặc kéo thả file vào cửa sổ); kiểm tra hình xem trước và danh sách Sự cố.
3. Nếu muốn, lưu chương trình vào thẻ SD (khung Thẻ SD).
4. Về gốc máy (Ctrl+H), rồi Chạy (Ctrl+R). Tạm dừng Ctrl+P, Tiếp tục Ctrl+Shift+P, Dừng Esc.
5. Chạy tay bằng Ctrl+mũi tên (X/Y) và Ctrl+PgUp/PgDn (Z); bước Alt+1/2/3.
Nếu mất kết nối, máy giữ nguyên vị trí; kết nối lại và chạy tiếp từ hộp thông báo.</translation>
    </message>
    <message>
        <source>Machine settings (&amp;$$)…</source>
        <translation>Cài đặt của &amp;máy ($$)…</translation>
    </message>
    <message>
        <source>&amp;Unlock ($X)</source>
        <translation>&amp;Mở khóa ($X)</translation>
    </message>
</context>
<context>
    <name>OperatorActions</name>
    <message>
        <source>%1 refused: %2</source>
        <translation>Không thực hiện %1: %2</translation>
    </message>
    <message>
        <source>Reconnecting…</source>
        <translation>Đang kết nối lại…</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>Chưa có chương trình</translation>
    </message>
    <message>
        <source>Open a G-code file first (File ▸ Open…).</source>
        <translation>Hãy mở một file G-code trước (Tệp ▸ Mở…).</translation>
    </message>
    <message numerus="yes">
        <source>%1 has %n error(s) (first: line %2: %3). Fix them before running.</source>
        <translation>
            <numerusform>%1 có %n lỗi (lỗi đầu tiên: dòng %2: %3). Hãy sửa trước khi chạy.</numerusform>
        </translation>
    </message>
    <message>
        <source>Program has errors</source>
        <translation>Chương trình có lỗi</translation>
    </message>
    <message>
        <source>Program leaves the travel</source>
        <translation>Chương trình vượt hành trình</translation>
    </message>
    <message>
        <source>Not homed</source>
        <translation>Chưa về gốc</translation>
    </message>
    <message>
        <source>Home the machine before starting a job (Machine ▸ Home).</source>
        <translation>Hãy cho máy về gốc trước khi chạy chương trình (Máy ▸ Về gốc máy).</translation>
    </message>
    <message>
        <source>Homing first; press “Home and restart” again once homed.</source>
        <translation>Đang về gốc trước; khi về gốc xong, bấm lại “Về gốc và chạy lại”.</translation>
    </message>
    <message>
        <source>Open a G-code file to save it to the card.</source>
        <translation>Hãy mở một file G-code để lưu vào thẻ nhớ.</translation>
    </message>
    <message>
        <source>not saved</source>
        <translation>chưa lưu</translation>
    </message>
    <message numerus="yes">
        <source>Opened %1: %n line(s) in %2 s</source>
        <translation>
            <numerusform>Đã mở %1: %n dòng trong %2 s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %n error(s); see the Problems list. It can be previewed but not run.</source>
        <translation>
            <numerusform>%1: %n lỗi; xem danh sách Sự cố. Có thể xem trước nhưng không chạy được.</numerusform>
        </translation>
    </message>
    <message>
        <source>Settings not saved</source>
        <translation>Chưa lưu cài đặt</translation>
    </message>
    <message>
        <source>Cannot write the settings file: %1</source>
        <translation>Không ghi được file cài đặt: %1</translation>
    </message>
    <message>
        <source>Settings saved and sent to the machine</source>
        <translation>Đã lưu cài đặt và gửi xuống máy</translation>
    </message>
    <message>
        <source>Settings saved</source>
        <translation>Đã lưu cài đặt</translation>
    </message>
</context>
<context>
    <name>OutlineBox</name>
    <message>
        <source>Outline</source>
        <translation>Đường bao</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Chạy đường bao</translation>
    </message>
    <message>
        <source>spindle off, at the job&apos;s top Z: trace where the job will cut (Pause holds it, Stop ends it)</source>
        <translation>tắt trục chính, ở Z cao nhất của chương trình: chạy theo vùng chương trình sẽ cắt (Tạm dừng giữ lại, Dừng kết thúc)</translation>
    </message>
    <message>
        <source>Convex hull</source>
        <translation>Bao lồi</translation>
    </message>
    <message>
        <source>trace the convex hull of the job instead of its bounding rectangle</source>
        <translation>chạy theo bao lồi của chương trình thay cho hình chữ nhật bao</translation>
    </message>
    <message>
        <source>No outline</source>
        <translation>Không có đường bao</translation>
    </message>
    <message>
        <source>Open a program without errors first.</source>
        <translation>Hãy mở một chương trình không có lỗi trước.</translation>
    </message>
    <message>
        <source>Outline leaves the travel</source>
        <translation>Đường bao vượt ra ngoài hành trình</translation>
    </message>
</context>
<context>
    <name>OverridesPanel</name>
    <message>
        <source>Overrides</source>
        <translation>Điều chỉnh tốc độ</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Chạy dao</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Trục chính</translation>
    </message>
    <message>
        <source>Rapid</source>
        <translation>Chạy nhanh</translation>
    </message>
    <message>
        <source>drag, then release to send</source>
        <translation>kéo, rồi thả ra để gửi</translation>
    </message>
    <message>
        <source>Machine: overrides not reported</source>
        <translation>Máy: chưa báo mức điều chỉnh</translation>
    </message>
    <message>
        <source>Machine: feed %1 %, spindle %2 %, rapid %3 %</source>
        <translation>Máy: chạy dao %1 %, trục chính %2 %, chạy nhanh %3 %</translation>
    </message>
</context>
<context>
    <name>PathGLView</name>
    <message>
        <source>no OpenGL context could be created</source>
        <translation>không tạo được ngữ cảnh OpenGL</translation>
    </message>
    <message>
        <source>the OpenGL driver has no glDrawElements</source>
        <translation>trình điều khiển OpenGL không có glDrawElements</translation>
    </message>
</context>
<context>
    <name>PointImportDialog</name>
    <message>
        <source>Import points: %1</source>
        <translation>Nhập điểm: %1</translation>
    </message>
    <message>
        <source>Fit X and Y into the travel (keeps the aspect)</source>
        <translation>Co giãn X và Y vừa hành trình (giữ tỉ lệ)</translation>
    </message>
    <message>
        <source>Cut every point at one Z</source>
        <translation>Cắt mọi điểm ở cùng một Z</translation>
    </message>
    <message>
        <source> mm/min</source>
        <translation> mm/phút</translation>
    </message>
    <message>
        <source>Scale (after fitting)</source>
        <translation>Tỉ lệ (sau khi co giãn)</translation>
    </message>
    <message>
        <source>Cut Z</source>
        <translation>Z cắt</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Tốc độ chạy dao</translation>
    </message>
    <message>
        <source>Clearance height</source>
        <translation>Độ cao an toàn</translation>
    </message>
    <message>
        <source>Convert and open</source>
        <translation>Chuyển đổi và mở</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Hủy</translation>
    </message>
    <message>
        <source>Converting…</source>
        <translation>Đang chuyển đổi…</translation>
    </message>
</context>
<context>
    <name>Ports</name>
    <message>
        <source>Built-in simulator (sim://)</source>
        <translation>Bộ mô phỏng có sẵn (sim://)</translation>
    </message>
    <message>
        <source>Built-in GRBL 1.1 simulator (sim://grbl)</source>
        <translation>Bộ mô phỏng GRBL 1.1 có sẵn (sim://grbl)</translation>
    </message>
    <message>
        <source>simulated machine (cnc-sim, process %1)</source>
        <translation>máy mô phỏng (cnc-sim, tiến trình %1)</translation>
    </message>
</context>
<context>
    <name>PositionPlot</name>
    <message>
        <source>time</source>
        <translation>thời gian</translation>
    </message>
    <message>
        <source>position</source>
        <translation>vị trí</translation>
    </message>
</context>
<context>
    <name>Preflight</name>
    <message>
        <source>Program leaves the travel</source>
        <translation>Chương trình vượt hành trình</translation>
    </message>
    <message>
        <source>Program not checked yet</source>
        <translation>Chương trình chưa kiểm tra xong</translation>
    </message>
    <message>
        <source>Start waits until the program is checked against the travel (a moment after it opens).</source>
        <translation>Lệnh chạy chờ đến khi chương trình được kiểm tra hành trình xong (ngay sau khi mở).</translation>
    </message>
    <message>
        <source>Start is disabled: line %1: %2</source>
        <translation>Không cho phép chạy: dòng %1: %2</translation>
    </message>
    <message numerus="yes">
        <source>(and %n more axis/direction(s))</source>
        <translation>
            <numerusform>(và %n trục/chiều khác)</numerusform>
        </translation>
    </message>
    <message>
        <source>Move the work zero or fix the program; in check mode it may be overridden.</source>
        <translation>Hãy dời gốc phôi hoặc sửa chương trình; khi chạy thử có thể bỏ qua kiểm tra này.</translation>
    </message>
</context>
<context>
    <name>Preview3D</name>
    <message>
        <source>the %1 platform cannot show OpenGL widgets</source>
        <translation>nền tảng %1 không hiển thị được widget OpenGL</translation>
    </message>
    <message>
        <source>no OpenGL context could be created on this display</source>
        <translation>không tạo được ngữ cảnh OpenGL trên màn hình này</translation>
    </message>
    <message>
        <source>the OpenGL context could not be used</source>
        <translation>không dùng được ngữ cảnh OpenGL</translation>
    </message>
    <message>
        <source>OpenGL %1.%2 found, 3.3 needed</source>
        <translation>có OpenGL %1.%2, cần 3.3</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Trên</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Trước</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Cạnh</translation>
    </message>
    <message>
        <source>Isometric</source>
        <translation>Đẳng cự</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Vừa khung</translation>
    </message>
    <message>
        <source>Largest deviation</source>
        <translation>Sai lệch lớn nhất</translation>
    </message>
    <message>
        <source>Show where the measured path strayed farthest from the programmed one</source>
        <translation>Chỉ ra chỗ đường đo được lệch xa nhất khỏi đường đã lập trình</translation>
    </message>
    <message>
        <source>drag: orbit · right drag or Shift+drag: pan · wheel: zoom at the cursor</source>
        <translation>kéo: xoay quanh · kéo chuột phải hoặc Shift+kéo: dịch · con lăn: phóng to tại con trỏ</translation>
    </message>
    <message>
        <source>The 3-D view starts when it is shown.</source>
        <translation>Hình 3-D khởi động khi được hiển thị.</translation>
    </message>
    <message>
        <source>The 3-D view cannot start: %1.
The 2-D view shows the program.</source>
        <translation>Hình 3-D không khởi động được: %1.
Hình 2-D hiển thị chương trình.</translation>
    </message>
    <message>
        <source>done</source>
        <translation>đã xong</translation>
    </message>
    <message>
        <source>measured:</source>
        <translation>đo được:</translation>
    </message>
    <message>
        <source>no cut measured yet</source>
        <translation>chưa đo được lần cắt nào</translation>
    </message>
    <message>
        <source>largest deviation %1 mm at X %2 Y %3 Z %4</source>
        <translation>sai lệch lớn nhất %1 mm tại X %2 Y %3 Z %4</translation>
    </message>
</context>
<context>
    <name>PreviewWidget</name>
    <message>
        <source>wheel: zoom · drag: pan · Ctrl+F: fit · Ctrl+G: grid</source>
        <translation>con lăn: phóng to/thu nhỏ · kéo: di chuyển · Ctrl+F: vừa khung · Ctrl+G: lưới</translation>
    </message>
    <message>
        <source>rapid</source>
        <translation>chạy dao nhanh</translation>
    </message>
    <message>
        <source>feed Z ≥ 0</source>
        <translation>chạy dao Z ≥ 0</translation>
    </message>
</context>
<context>
    <name>ProgramPanel</name>
    <message>
        <source>Line</source>
        <translation>Dòng</translation>
    </message>
    <message>
        <source>Col</source>
        <translation>Cột</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Nội dung</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Mã nguồn</translation>
    </message>
    <message>
        <source>No program open. File ▸ Open… or drop a G-code file on the window.</source>
        <translation>Chưa mở chương trình nào. Tệp ▸ Mở… hoặc kéo thả file G-code vào cửa sổ.</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>Sự cố</translation>
    </message>
    <message>
        <source>No program open.</source>
        <translation>Chưa mở chương trình nào.</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n lỗi</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n cảnh báo</numerusform>
        </translation>
    </message>
    <message>
        <source>Problems (%1)</source>
        <translation>Sự cố (%1)</translation>
    </message>
    <message>
        <source>Start here</source>
        <translation>Chạy từ đây</translation>
    </message>
    <message numerus="yes">
        <source>Tool %1 is not in the tool table: edit the tool table…</source>
        <translation>
            <numerusform>Dao %1 không có trong bảng dao: sửa bảng dao…</numerusform>
        </translation>
    </message>
    <message>
        <source>error</source>
        <translation>lỗi</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>cảnh báo</translation>
    </message>
    <message>
        <source>in subprogram %1</source>
        <translation>trong chương trình con %1</translation>
    </message>
    <message>
        <source>loop pass %1</source>
        <translation>vòng lặp lần %1</translation>
    </message>
</context>
<context>
    <name>ProgramStops</name>
    <message>
        <source>Program stop at %1: waiting for the operator</source>
        <translation>Dừng chương trình ở %1: chờ người vận hành</translation>
    </message>
    <message>
        <source>Settings not saved</source>
        <translation>Chưa lưu cài đặt</translation>
    </message>
</context>
<context>
    <name>QFileDialog</name>
    <message>
        <source>Look in:</source>
        <translation>Tìm trong:</translation>
    </message>
    <message>
        <source>File &amp;name:</source>
        <translation>&amp;Tên file:</translation>
    </message>
    <message>
        <source>Files of type:</source>
        <translation>Loại file:</translation>
    </message>
    <message>
        <source>&amp;Open</source>
        <translation>&amp;Mở</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Lưu</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Lùi</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Tới</translation>
    </message>
    <message>
        <source>Parent Directory</source>
        <translation>Thư mục cha</translation>
    </message>
    <message>
        <source>Create New Folder</source>
        <translation>Tạo thư mục mới</translation>
    </message>
    <message>
        <source>List View</source>
        <translation>Dạng danh sách</translation>
    </message>
    <message>
        <source>Detail View</source>
        <translation>Dạng chi tiết</translation>
    </message>
</context>
<context>
    <name>QFileSystemModel</name>
    <message>
        <source>Name</source>
        <translation>Tên</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Kích thước</translation>
    </message>
    <message>
        <source>Date Modified</source>
        <translation>Ngày sửa</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Loại</translation>
    </message>
</context>
<context>
    <name>QMessageBox</name>
    <message>
        <source>About Qt</source>
        <translation>Giới thiệu Qt</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <translation>Đồng ý</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Hủy</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Đóng</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Khôi phục mặc định</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Áp dụng</translation>
    </message>
    <message>
        <source>Yes</source>
        <translation>Có</translation>
    </message>
    <message>
        <source>No</source>
        <translation>Không</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Mở</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Lưu</translation>
    </message>
    <message>
        <source>Show Details...</source>
        <translation>Xem chi tiết...</translation>
    </message>
    <message>
        <source>Hide Details...</source>
        <translation>Ẩn chi tiết...</translation>
    </message>
</context>
<context>
    <name>SdPanel</name>
    <message>
        <source>a card name has 1 to 32 letters, digits, &apos;_&apos;, &apos;-&apos; or &apos;.&apos;</source>
        <translation>tên trên thẻ gồm 1 đến 32 chữ cái không dấu, chữ số, &apos;_&apos;, &apos;-&apos; hoặc &apos;.&apos;</translation>
    </message>
    <message>
        <source>name on the card</source>
        <translation>tên trên thẻ nhớ</translation>
    </message>
    <message>
        <source>Save program to SD</source>
        <translation>Lưu chương trình vào SD</translation>
    </message>
    <message>
        <source>send the open program to the card; the machine checks every line</source>
        <translation>gửi chương trình đang mở vào thẻ nhớ; máy kiểm tra từng dòng</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Tên</translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation>Byte</translation>
    </message>
    <message>
        <source>Lines</source>
        <translation>Dòng</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Làm mới</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Xóa</translation>
    </message>
    <message>
        <source>Run from SD</source>
        <translation>Chạy từ SD</translation>
    </message>
    <message>
        <source>the machine runs the file on its own, even without this computer</source>
        <translation>máy tự chạy file, kể cả khi không có máy tính này</translation>
    </message>
    <message>
        <source>uploading…</source>
        <translation>đang gửi…</translation>
    </message>
</context>
<context>
    <name>SessionBinder</name>
    <message>
        <source>Open failed</source>
        <translation>Không mở được file</translation>
    </message>
    <message>
        <source>Cannot open file</source>
        <translation>Không mở được file</translation>
    </message>
    <message>
        <source>Link error</source>
        <translation>Lỗi kết nối</translation>
    </message>
    <message>
        <source>Cannot connect</source>
        <translation>Không kết nối được</translation>
    </message>
    <message>
        <source>The port could not be opened: %1</source>
        <translation>Không mở được cổng: %1</translation>
    </message>
    <message>
        <source>the port failed; details in the console</source>
        <translation>cổng bị lỗi; chi tiết ở bảng lệnh</translation>
    </message>
    <message>
        <source>%1 % resends</source>
        <translation>%1 % gửi lại</translation>
    </message>
    <message>
        <source>resends in the last minute: %1 % of %2 frames</source>
        <translation>gửi lại trong phút vừa qua: %1 % của %2 khung</translation>
    </message>
    <message>
        <source>this computer</source>
        <translation>máy tính này</translation>
    </message>
    <message>
        <source>the machine&apos;s panel</source>
        <translation>bảng điều khiển của máy</translation>
    </message>
    <message>
        <source>the cover</source>
        <translation>nắp che</translation>
    </message>
    <message>
        <source>the link</source>
        <translation>kết nối</translation>
    </message>
    <message>
        <source>the program</source>
        <translation>chương trình</translation>
    </message>
    <message>
        <source>the machine</source>
        <translation>máy</translation>
    </message>
    <message>
        <source>Machine holds (%1): %2</source>
        <translation>Máy đang tạm dừng (%1): %2</translation>
    </message>
    <message>
        <source>Machine stopped (%1): %2</source>
        <translation>Máy đã dừng (%1): %2</translation>
    </message>
    <message>
        <source>Machine alarm</source>
        <translation>Máy báo lỗi</translation>
    </message>
    <message numerus="yes">
        <source>saved as %1: %n line(s), verified by the card&apos;s CRC32</source>
        <translation>
            <numerusform>đã lưu thành %1: %n dòng, đã kiểm tra bằng CRC32 của thẻ</numerusform>
        </translation>
    </message>
    <message>
        <source>not saved: %1</source>
        <translation>chưa lưu: %1</translation>
    </message>
    <message>
        <source>Job finished</source>
        <translation>Chương trình đã chạy xong</translation>
    </message>
    <message>
        <source>Job ended</source>
        <translation>Chương trình đã dừng</translation>
    </message>
    <message>
        <source>The job did not complete: %1</source>
        <translation>Chương trình chưa chạy hết: %1</translation>
    </message>
    <message>
        <source>line %1 was refused: %2</source>
        <translation>dòng %1 bị máy từ chối: %2</translation>
    </message>
    <message>
        <source> (at line %1; the console has the details)</source>
        <translation> (tại dòng %1; chi tiết ở cửa sổ lệnh)</translation>
    </message>
    <message>
        <source>SD %1 · </source>
        <translation>SD %1 · </translation>
    </message>
    <message>
        <source>Machine refused</source>
        <translation>Máy từ chối lệnh</translation>
    </message>
</context>
<context>
    <name>SettingsDialog</name>
    <message>
        <source>PID gains</source>
        <translation>Hệ số PID</translation>
    </message>
    <message>
        <source>Feeds &amp;&amp; motion</source>
        <translation>Chạy dao &amp;&amp; chuyển động</translation>
    </message>
    <message>
        <source>Link &amp;&amp; heartbeat</source>
        <translation>Kết nối &amp;&amp; nhịp tim</translation>
    </message>
    <message>
        <source>Axis drive</source>
        <translation>Truyền động trục</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Trục chính</translation>
    </message>
    <message>
        <source>Travel &amp;&amp; offset</source>
        <translation>Hành trình &amp;&amp; gốc phôi</translation>
    </message>
    <message>
        <source>Program stops &amp;&amp; end</source>
        <translation>Dừng chương trình &amp;&amp; kết thúc</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Cài đặt</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Ngôn ngữ</translation>
    </message>
    <message>
        <source>the window&apos;s language; it changes at once</source>
        <translation>ngôn ngữ của cửa sổ; đổi ngay lập tức</translation>
    </message>
    <message>
        <source>PID gains are pushed to the machine (SET) when you press OK while connected.</source>
        <translation>Hệ số PID được gửi xuống máy (SET) khi bấm Đồng ý lúc đang kết nối.</translation>
    </message>
    <message>
        <source>range %1 … %2</source>
        <translation>phạm vi %1 … %2</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>Chưa lưu: %1</translation>
    </message>
</context>
<context>
    <name>SettingsFields</name>
    <message>
        <source>supply voltage (V)</source>
        <translation>điện áp nguồn (V)</translation>
    </message>
    <message>
        <source>bridge drop (V)</source>
        <translation>sụt áp cầu H (V)</translation>
    </message>
    <message>
        <source>no-load speed (rpm)</source>
        <translation>tốc độ không tải (vòng/phút)</translation>
    </message>
    <message>
        <source>gear ratio</source>
        <translation>tỉ số truyền</translation>
    </message>
    <message>
        <source>encoder pulses per turn</source>
        <translation>số xung encoder mỗi vòng</translation>
    </message>
    <message>
        <source>quadrature edges</source>
        <translation>số cạnh xung đếm (x4)</translation>
    </message>
    <message>
        <source>screw lead (mm)</source>
        <translation>bước vít me (mm)</translation>
    </message>
    <message>
        <source>X travel (mm)</source>
        <translation>hành trình X (mm)</translation>
    </message>
    <message>
        <source>Y travel (mm)</source>
        <translation>hành trình Y (mm)</translation>
    </message>
    <message>
        <source>Z travel (mm)</source>
        <translation>hành trình Z (mm)</translation>
    </message>
    <message>
        <source>home back-off (mm)</source>
        <translation>lùi sau khi về gốc (mm)</translation>
    </message>
    <message>
        <source>work offset X (mm)</source>
        <translation>gốc phôi X (mm)</translation>
    </message>
    <message>
        <source>work offset Y (mm)</source>
        <translation>gốc phôi Y (mm)</translation>
    </message>
    <message>
        <source>work offset Z (mm)</source>
        <translation>gốc phôi Z (mm)</translation>
    </message>
    <message>
        <source>rapid feed (mm/min)</source>
        <translation>tốc độ chạy dao nhanh (mm/phút)</translation>
    </message>
    <message>
        <source>maximum feed (mm/min)</source>
        <translation>tốc độ chạy dao tối đa (mm/phút)</translation>
    </message>
    <message>
        <source>acceleration (mm/s²)</source>
        <translation>gia tốc (mm/s²)</translation>
    </message>
    <message>
        <source>jerk (mm/s³)</source>
        <translation>độ giật (mm/s³)</translation>
    </message>
    <message>
        <source>junction deviation (mm)</source>
        <translation>sai lệch tại điểm nối (mm)</translation>
    </message>
    <message>
        <source>arc tolerance (mm)</source>
        <translation>dung sai cung tròn (mm)</translation>
    </message>
    <message>
        <source>homing feed (mm/min)</source>
        <translation>tốc độ về gốc (mm/phút)</translation>
    </message>
    <message>
        <source>Kp (proportional)</source>
        <translation>Kp (tỉ lệ)</translation>
    </message>
    <message>
        <source>Ki (integral)</source>
        <translation>Ki (tích phân)</translation>
    </message>
    <message>
        <source>Kd (derivative)</source>
        <translation>Kd (vi phân)</translation>
    </message>
    <message>
        <source>control loop rate (Hz)</source>
        <translation>tần số vòng điều khiển (Hz)</translation>
    </message>
    <message>
        <source>following error limit (mm)</source>
        <translation>giới hạn sai lệch bám (mm)</translation>
    </message>
    <message>
        <source>heartbeat period (s)</source>
        <translation>chu kỳ nhịp tim (s)</translation>
    </message>
    <message>
        <source>degraded after (s)</source>
        <translation>báo chập chờn sau (s)</translation>
    </message>
    <message>
        <source>lost after (s)</source>
        <translation>báo mất kết nối sau (s)</translation>
    </message>
    <message>
        <source>baud rate</source>
        <translation>tốc độ baud</translation>
    </message>
    <message>
        <source>optional stop M01 (1 holds, 0 skips)</source>
        <translation>dừng tùy chọn M01 (1 dừng, 0 bỏ qua)</translation>
    </message>
    <message>
        <source>stop the spindle at M00/M01</source>
        <translation>tắt trục chính khi gặp M00/M01</translation>
    </message>
    <message>
        <source>after the job</source>
        <translation>sau khi chạy xong</translation>
    </message>
    <message>
        <source>motor supply voltage</source>
        <translation>điện áp cấp cho động cơ</translation>
    </message>
    <message>
        <source>voltage lost in the L298N</source>
        <translation>điện áp sụt trên L298N</translation>
    </message>
    <message>
        <source>output shaft rpm unloaded at supply_v</source>
        <translation>tốc độ trục ra khi không tải ở điện áp nguồn</translation>
    </message>
    <message>
        <source>motor turns per output turn</source>
        <translation>số vòng động cơ cho một vòng trục ra</translation>
    </message>
    <message>
        <source>pulses per motor turn per channel</source>
        <translation>số xung mỗi vòng động cơ trên một kênh</translation>
    </message>
    <message>
        <source>edges counted per pulse</source>
        <translation>số cạnh được đếm trên một xung</translation>
    </message>
    <message>
        <source>lead screw travel per output turn</source>
        <translation>quãng chạy của vít me cho một vòng trục ra</translation>
    </message>
    <message>
        <source>back-off from each switch after homing</source>
        <translation>khoảng lùi khỏi mỗi công tắc hành trình sau khi về gốc</translation>
    </message>
    <message>
        <source>default work offset X</source>
        <translation>gốc phôi X mặc định</translation>
    </message>
    <message>
        <source>default work offset Y</source>
        <translation>gốc phôi Y mặc định</translation>
    </message>
    <message>
        <source>default work offset Z</source>
        <translation>gốc phôi Z mặc định</translation>
    </message>
    <message>
        <source>G00 feed</source>
        <translation>tốc độ G00</translation>
    </message>
    <message>
        <source>cap on programmed feeds</source>
        <translation>mức trần cho tốc độ chạy dao trong chương trình</translation>
    </message>
    <message>
        <source>chord error when arcs become lines</source>
        <translation>sai số dây cung khi chia cung tròn thành đoạn thẳng</translation>
    </message>
    <message>
        <source>M01 holds the job (1) or is skipped (0)</source>
        <translation>M01 dừng chương trình (1) hoặc bị bỏ qua (0)</translation>
    </message>
    <message>
        <source>M00/M01 also stop the spindle (1)</source>
        <translation>M00/M01 tắt luôn trục chính (1)</translation>
    </message>
    <message>
        <source>after the job: 0 stay, 1 lift Z, 2 work zero X0 Y0, 3 home</source>
        <translation>sau khi chạy xong: 0 đứng yên, 1 nâng Z, 2 về X0 Y0 của gốc phôi, 3 về gốc máy</translation>
    </message>
    <message>
        <source>stay where it ends</source>
        <translation>đứng yên tại chỗ kết thúc</translation>
    </message>
    <message>
        <source>lift Z to the top</source>
        <translation>nâng Z lên trên cùng</translation>
    </message>
    <message>
        <source>lift Z, then go to work X0 Y0</source>
        <translation>nâng Z, rồi về X0 Y0 của phôi</translation>
    </message>
    <message>
        <source>home the machine</source>
        <translation>về gốc máy</translation>
    </message>
    <message>
        <source>skip M01</source>
        <translation>bỏ qua M01</translation>
    </message>
    <message>
        <source>hold at M01</source>
        <translation>dừng tại M01</translation>
    </message>
    <message>
        <source>keep the spindle turning</source>
        <translation>giữ trục chính quay</translation>
    </message>
    <message>
        <source>stop the spindle</source>
        <translation>dừng trục chính</translation>
    </message>
</context>
<context>
    <name>SourceModel</name>
    <message numerus="yes">
        <source>%n move(s)</source>
        <translation>
            <numerusform>%n đoạn dịch chuyển</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… và %n dòng nữa</numerusform>
        </translation>
    </message>
    <message>
        <source>Machine lines made by line %1:</source>
        <translation>Các dòng lệnh máy sinh ra từ dòng %1:</translation>
    </message>
</context>
<context>
    <name>StartHere</name>
    <message>
        <source>Start here</source>
        <translation>Chạy từ đây</translation>
    </message>
    <message>
        <source>Nothing runs from line %1 on.</source>
        <translation>Từ dòng %1 trở đi không còn gì để chạy.</translation>
    </message>
    <message>
        <source>(nothing to restore)</source>
        <translation>(không có gì cần khôi phục)</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Chạy</translation>
    </message>
    <message>
        <source>Start the job at line %1 of %2?</source>
        <translation>Chạy chương trình từ dòng %1 trên %2?</translation>
    </message>
    <message>
        <source>Units mm, absolute distances, XY plane (the machine&apos;s dialect).</source>
        <translation>Đơn vị mm, tọa độ tuyệt đối, mặt phẳng XY (quy ước của máy).</translation>
    </message>
    <message>
        <source>Feed F%1.</source>
        <translation>Tốc độ chạy dao F%1.</translation>
    </message>
    <message>
        <source>No feed yet.</source>
        <translation>Chưa có tốc độ chạy dao.</translation>
    </message>
    <message>
        <source>Spindle on at S%1, up to speed before moving.</source>
        <translation>Bật trục chính ở S%1, đạt tốc độ rồi mới di chuyển.</translation>
    </message>
    <message>
        <source>Spindle off.</source>
        <translation>Tắt trục chính.</translation>
    </message>
    <message>
        <source>Retract to Z%1, rapid to X%2 Y%3, feed down to Z%4.</source>
        <translation>Rút dao lên Z%1, chạy nhanh tới X%2 Y%3, ăn dao xuống Z%4.</translation>
    </message>
    <message>
        <source>No tool change comes before this line: the tool the program starts with must be in the spindle.</source>
        <translation>Không có lần thay dao nào trước dòng này: dao mà chương trình bắt đầu với nó phải đang lắp trên trục chính.</translation>
    </message>
    <message>
        <source>The tool of the last tool change before this line (it names no number) must be in the spindle.</source>
        <translation>Dao của lần thay dao cuối cùng trước dòng này (không ghi số dao) phải đang lắp trên trục chính.</translation>
    </message>
    <message>
        <source>Tool T%1 must be in the spindle (the last tool change before this line).</source>
        <translation>Dao T%1 phải đang lắp trên trục chính (lần thay dao cuối cùng trước dòng này).</translation>
    </message>
    <message>
        <source>The machine moved since the program was read from its position: choose Start here again.</source>
        <translation>Máy đã di chuyển sau khi chương trình được đọc từ vị trí của nó: hãy chọn lại “Chạy từ đây”.</translation>
    </message>
</context>
<context>
    <name>StateTable</name>
    <message>
        <source>Not now: %1</source>
        <translation>Chưa được lúc này: %1</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>chưa kết nối</translation>
    </message>
    <message>
        <source>still connecting</source>
        <translation>đang kết nối</translation>
    </message>
    <message>
        <source>the link is unsteady: only Pause, Stop and Spindle off</source>
        <translation>đường truyền chập chờn: chỉ được Tạm dừng, Dừng và Tắt trục chính</translation>
    </message>
    <message>
        <source>the link is lost: reconnect first</source>
        <translation>mất kết nối: hãy kết nối lại trước</translation>
    </message>
    <message>
        <source>the machine is homing</source>
        <translation>máy đang về gốc</translation>
    </message>
    <message>
        <source>the machine is moving (jog)</source>
        <translation>máy đang di chuyển (chạy tay)</translation>
    </message>
    <message>
        <source>the spindle is changing speed</source>
        <translation>trục chính đang đổi tốc độ</translation>
    </message>
    <message>
        <source>a job is running</source>
        <translation>đang chạy một chương trình</translation>
    </message>
    <message>
        <source>a job is running from the SD card</source>
        <translation>đang chạy một chương trình từ thẻ SD</translation>
    </message>
    <message>
        <source>a program is being saved to the SD card</source>
        <translation>đang lưu một chương trình vào thẻ SD</translation>
    </message>
    <message>
        <source>the job is held: resume or stop it first</source>
        <translation>chương trình đang tạm dừng: hãy tiếp tục hoặc dừng nó trước</translation>
    </message>
    <message>
        <source>the job waits at a program stop</source>
        <translation>chương trình đang chờ tại một điểm dừng</translation>
    </message>
    <message>
        <source>the machine is in alarm: home it first</source>
        <translation>máy đang báo động: hãy về gốc trước</translation>
    </message>
    <message>
        <source>the cover is open</source>
        <translation>nắp che đang mở</translation>
    </message>
    <message>
        <source>nothing is moving</source>
        <translation>không có gì đang chuyển động</translation>
    </message>
    <message>
        <source>nothing is held</source>
        <translation>không có gì đang tạm dừng</translation>
    </message>
    <message>
        <source>only in check mode</source>
        <translation>chỉ khi chạy thử</translation>
    </message>
    <message>
        <source>check mode is on</source>
        <translation>đang bật chạy thử</translation>
    </message>
    <message>
        <source>the machine is not in alarm</source>
        <translation>máy không ở trạng thái báo động</translation>
    </message>
    <message>
        <source>home the machine first</source>
        <translation>hãy cho máy về gốc trước</translation>
    </message>
    <message>
        <source>answer the open dialog first</source>
        <translation>hãy trả lời hộp thoại đang mở trước</translation>
    </message>
    <message>
        <source>open a program that can run first</source>
        <translation>hãy mở một chương trình chạy được trước</translation>
    </message>
    <message>
        <source>this machine has no SD card</source>
        <translation>máy này không có thẻ SD</translation>
    </message>
    <message>
        <source>this machine has no panel of its own</source>
        <translation>máy này không có bảng điều khiển riêng</translation>
    </message>
    <message>
        <source>this machine has no cover switch</source>
        <translation>máy này không có công tắc nắp che</translation>
    </message>
    <message>
        <source>this machine takes no overrides</source>
        <translation>máy này không nhận điều chỉnh tốc độ</translation>
    </message>
    <message>
        <source>this machine has no settings table of its own: its settings are in File &gt; Settings</source>
        <translation>máy này không có bảng cài đặt riêng: các cài đặt của nó nằm ở Tệp &gt; Cài đặt</translation>
    </message>
    <message>
        <source>this machine has no alarm lock to lift: home it</source>
        <translation>máy này không có khóa báo động để mở: hãy cho máy về gốc</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>Về gốc máy</translation>
    </message>
    <message>
        <source>Home after a fault</source>
        <translation>Về gốc sau sự cố</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Chạy</translation>
    </message>
    <message>
        <source>Start here</source>
        <translation>Chạy từ đây</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Tạm dừng</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Tiếp tục</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Dừng</translation>
    </message>
    <message>
        <source>Jog</source>
        <translation>Chạy tay (jog)</translation>
    </message>
    <message>
        <source>Spindle on</source>
        <translation>Bật trục chính</translation>
    </message>
    <message>
        <source>Spindle off</source>
        <translation>Tắt trục chính</translation>
    </message>
    <message>
        <source>Work zero</source>
        <translation>Đặt gốc phôi</translation>
    </message>
    <message>
        <source>Check mode</source>
        <translation>Chạy thử</translation>
    </message>
    <message>
        <source>Override travel check</source>
        <translation>Bỏ qua kiểm tra hành trình</translation>
    </message>
    <message>
        <source>Save to SD</source>
        <translation>Lưu vào SD</translation>
    </message>
    <message>
        <source>SD card list</source>
        <translation>Danh sách thẻ SD</translation>
    </message>
    <message>
        <source>Delete from SD</source>
        <translation>Xóa khỏi SD</translation>
    </message>
    <message>
        <source>Run from SD</source>
        <translation>Chạy từ SD</translation>
    </message>
    <message>
        <source>MDI line</source>
        <translation>Dòng MDI</translation>
    </message>
    <message>
        <source>Hold to jog</source>
        <translation>Giữ để chạy tay</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Chạy đường bao</translation>
    </message>
    <message>
        <source>MDI command</source>
        <translation>Lệnh MDI</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Kết nối</translation>
    </message>
    <message>
        <source>Machine panel</source>
        <translation>Bảng điều khiển máy</translation>
    </message>
    <message>
        <source>Cover switch</source>
        <translation>Công tắc nắp che</translation>
    </message>
    <message>
        <source>Work offsets</source>
        <translation>Gốc phôi</translation>
    </message>
    <message>
        <source>Go to position</source>
        <translation>Đi tới vị trí</translation>
    </message>
    <message>
        <source>Custom command</source>
        <translation>Lệnh tự định nghĩa</translation>
    </message>
    <message>
        <source>Feed override</source>
        <translation>Điều chỉnh chạy dao</translation>
    </message>
    <message>
        <source>Spindle override</source>
        <translation>Điều chỉnh trục chính</translation>
    </message>
    <message>
        <source>Rapid override</source>
        <translation>Điều chỉnh chạy nhanh</translation>
    </message>
    <message>
        <source>Machine settings ($$)</source>
        <translation>Cài đặt của máy ($$)</translation>
    </message>
    <message>
        <source>Unlock ($X)</source>
        <translation>Mở khóa ($X)</translation>
    </message>
</context>
<context>
    <name>StopPrompt</name>
    <message>
        <source>Continue</source>
        <translation>Tiếp tục</translation>
    </message>
    <message>
        <source>Stop job</source>
        <translation>Dừng chương trình</translation>
    </message>
    <message>
        <source>Tool change</source>
        <translation>Thay dao</translation>
    </message>
    <message>
        <source>Program stop</source>
        <translation>Dừng chương trình</translation>
    </message>
    <message>
        <source>Before continuing you may jog and set a work zero (touch off); Continue first brings the tool back above where it stopped.</source>
        <translation>Trước khi tiếp tục, bạn có thể chạy tay (jog) và đặt gốc phôi (so dao); Tiếp tục sẽ đưa dao về lại phía trên chỗ đã dừng trước.</translation>
    </message>
    <message>
        <source>Tool change at line %1 (%2): the spindle is off and Z is up.</source>
        <translation>Thay dao ở dòng %1 (%2): trục chính đã tắt và Z đã nâng lên.</translation>
    </message>
    <message>
        <source>Optional stop</source>
        <translation>Dừng tùy chọn</translation>
    </message>
    <message>
        <source>%1 at line %2 (%3): the machine holds.</source>
        <translation>%1 ở dòng %2 (%3): máy đang dừng chờ.</translation>
    </message>
    <message>
        <source>Continue goes on with the next line.</source>
        <translation>Tiếp tục sẽ chạy dòng kế tiếp.</translation>
    </message>
    <message>
        <source>Fit the next tool (the program names none).</source>
        <translation>Lắp dao tiếp theo (chương trình không ghi số dao).</translation>
    </message>
    <message>
        <source>Fit tool %1 (diameter unknown: not in the tool table).</source>
        <translation>Lắp dao %1 (chưa biết đường kính: không có trong bảng dao).</translation>
    </message>
    <message>
        <source>Fit tool %1 (diameter %2 mm).</source>
        <translation>Lắp dao %1 (đường kính %2 mm).</translation>
    </message>
    <message>
        <source>Continue restarts the spindle, lowers Z and goes on.</source>
        <translation>Tiếp tục sẽ bật lại trục chính, hạ Z rồi chạy tiếp.</translation>
    </message>
</context>
<context>
    <name>Summary</name>
    <message numerus="yes">
        <source>%n line(s)</source>
        <translation>
            <numerusform>%n dòng</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n machine line(s)</source>
        <translation>
            <numerusform>%n dòng lệnh máy</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n move(s)</source>
        <translation>
            <numerusform>%n đoạn di chuyển</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 → %2, %3</source>
        <translation>%1 → %2, %3</translation>
    </message>
    <message>
        <source>cut %1 mm, rapid %2 mm, estimated %3</source>
        <translation>cắt %1 mm, chạy nhanh %2 mm, ước tính %3</translation>
    </message>
    <message>
        <source>program stops: %1 (tool changes: %2), not in the estimate: %3 of machine moves, plus the operator&apos;s wait</source>
        <translation>điểm dừng chương trình: %1 (thay dao: %2), không tính vào thời gian ước tính: %3 máy chạy, cộng thời gian người vận hành chờ</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n lỗi</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n cảnh báo</numerusform>
        </translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
</context>
<context>
    <name>ToolTableDialog</name>
    <message>
        <source>Tool table</source>
        <translation>Bảng dao</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Dao</translation>
    </message>
    <message>
        <source>Diameter (mm)</source>
        <translation>Đường kính (mm)</translation>
    </message>
    <message>
        <source>Length (mm)</source>
        <translation>Chiều dài (mm)</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Ghi chú</translation>
    </message>
    <message>
        <source>Add tool</source>
        <translation>Thêm dao</translation>
    </message>
    <message>
        <source>Remove tool</source>
        <translation>Xóa dao</translation>
    </message>
    <message>
        <source>tool number</source>
        <translation>số dao</translation>
    </message>
    <message>
        <source>diameter</source>
        <translation>đường kính</translation>
    </message>
    <message>
        <source>length</source>
        <translation>chiều dài</translation>
    </message>
    <message>
        <source>row %1: %2 &apos;%3&apos; is not a number</source>
        <translation>dòng %1: %2 &apos;%3&apos; không phải là số</translation>
    </message>
    <message>
        <source>row %1: %2</source>
        <translation>dòng %1: %2</translation>
    </message>
    <message>
        <source>row %1: tool %2 is listed twice</source>
        <translation>dòng %1: dao %2 có hai lần trong bảng</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>Chưa lưu: %1</translation>
    </message>
    <message>
        <source>Cannot write the tool table: %1</source>
        <translation>Không ghi được bảng dao: %1</translation>
    </message>
    <message>
        <source>Tool table not saved</source>
        <translation>Chưa lưu bảng dao</translation>
    </message>
    <message>
        <source>Tool table saved: it applies to the next program opened</source>
        <translation>Đã lưu bảng dao: áp dụng cho chương trình mở tiếp theo</translation>
    </message>
</context>
</TS>
