<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru_RU">
<context>
    <name>Language</name>
    <message>
        <location filename="../ui/language.cpp" line="16"/>
        <source>System Default</source>
        <translation>Как в системе</translation>
    </message>
</context>
<context>
    <name>NumberText</name>
    <message>
        <location filename="../ui/editor/number_text.cpp" line="31"/>
        <source>“%1” is out of range</source>
        <translation>«%1» вне допустимого диапазона</translation>
    </message>
    <message>
        <location filename="../ui/editor/number_text.cpp" line="33"/>
        <source>“%1” is not a number</source>
        <translation>«%1» — не число</translation>
    </message>
</context>
<context>
    <name>ObjectRef</name>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="50"/>
        <source>Plane</source>
        <translation>Плоскость</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="51"/>
        <source>Cylinder</source>
        <translation>Цилиндр</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="49"/>
        <source>Ball</source>
        <translation>Шар</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="53"/>
        <source>Planes</source>
        <translation>Плоскости</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="54"/>
        <source>Cylinders</source>
        <translation>Цилиндры</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="52"/>
        <source>Balls</source>
        <translation>Шары</translation>
    </message>
    <message>
        <location filename="../ui/editor/object_ref.cpp" line="68"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
</context>
<context>
    <name>carom::ui::AccuracyWindow</name>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="39"/>
        <source>Speed vs accuracy</source>
        <translation>Скорость и точность</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="41"/>
        <source>Position error against exact (m)</source>
        <translation>Ошибка положения относительно exact (m)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="41"/>
        <source>Relative energy drift</source>
        <translation>Относительный дрейф энергии</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="42"/>
        <source>Deepest penetration (m)</source>
        <translation>Максимальная глубина проникновения (m)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="42"/>
        <source>Escaped balls</source>
        <translation>Вылетевшие шары</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="48"/>
        <location filename="../ui/accuracy_window.cpp" line="71"/>
        <source>Computing time (s)</source>
        <translation>Время вычислений (s)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="71"/>
        <source>Run</source>
        <translation>Прогон</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="71"/>
        <source>Position error</source>
        <translation>Ошибка положения</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="72"/>
        <source>Energy drift</source>
        <translation>Дрейф энергии</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="72"/>
        <source>Penetration</source>
        <translation>Проникновение</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="72"/>
        <source>Escaped</source>
        <translation>Вылетело</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="79"/>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="81"/>
        <source>Apply Selected Settings</source>
        <translation>Применить выбранные настройки</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="88"/>
        <source>Each point is one run of the current scene; lower and further left is better. Choose a run to use its settings.</source>
        <translation>Каждая точка — один прогон текущей сцены; чем ниже и левее, тем лучше. Выберите прогон, чтобы применить его настройки.</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="95"/>
        <source>Error:</source>
        <translation>Ошибка:</translation>
    </message>
</context>
<context>
    <name>carom::ui::EditorTools</name>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="137"/>
        <source>Change Velocity</source>
        <translation>Изменить скорость</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="124"/>
        <source>Turn Plane</source>
        <translation>Повернуть плоскость</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="130"/>
        <source>Turn Cylinder</source>
        <translation>Повернуть цилиндр</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="226"/>
        <source>Move</source>
        <translation>Переместить</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="277"/>
        <source>Click on a surface or on the ground to place an object.</source>
        <translation>Щёлкните по поверхности или по земле, чтобы поставить объект.</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="301"/>
        <source>Add Ball</source>
        <translation>Добавить шар</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="306"/>
        <source>No room for a ball there: %1</source>
        <translation>Здесь нет места для шара: %1</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="318"/>
        <source>Add Plane</source>
        <translation>Добавить плоскость</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="328"/>
        <source>Add Cylinder</source>
        <translation>Добавить цилиндр</translation>
    </message>
    <message>
        <location filename="../ui/editor/editor_tools.cpp" line="331"/>
        <source>Cannot place it there: %1</source>
        <translation>Сюда поставить нельзя: %1</translation>
    </message>
</context>
<context>
    <name>carom::ui::EnergyPlot</name>
    <message>
        <location filename="../ui/energy_plot.cpp" line="35"/>
        <source>Kinetic</source>
        <translation>Кинетическая</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="36"/>
        <source>Potential</source>
        <translation>Потенциальная</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="37"/>
        <source>Total</source>
        <translation>Полная</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="38"/>
        <source>Simulated time (s)</source>
        <translation>Модельное время (s)</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="39"/>
        <source>Energy (J)</source>
        <translation>Энергия (J)</translation>
    </message>
</context>
<context>
    <name>carom::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="80"/>
        <source>Energy</source>
        <translation>Энергия</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="151"/>
        <location filename="../ui/main_window.cpp" line="157"/>
        <source>&amp;Run</source>
        <translation>&amp;Запуск</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="155"/>
        <source>Run or pause the simulation (Space)</source>
        <translation>Запустить или приостановить симуляцию (Пробел)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="157"/>
        <source>&amp;Pause</source>
        <translation>&amp;Пауза</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="161"/>
        <source>&amp;Step</source>
        <translation>&amp;Шаг</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="163"/>
        <source>Advance one time step (S)</source>
        <translation>Выполнить один шаг по времени (S)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="169"/>
        <source>R&amp;eset</source>
        <translation>&amp;Сброс</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="171"/>
        <source>Back to the scene&apos;s initial state (R)</source>
        <translation>Вернуть сцену в начальное состояние (R)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="177"/>
        <source>&amp;Full Screen</source>
        <translation>&amp;Полноэкранный режим</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="183"/>
        <source>&amp;Follow Ball</source>
        <translation>&amp;Следить за шаром</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="189"/>
        <source>&amp;Explosions</source>
        <translation>&amp;Взрывы</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="196"/>
        <source>&amp;Antialiasing</source>
        <translation>&amp;Сглаживание</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="208"/>
        <source>&amp;Mute</source>
        <translation>Без &amp;звука</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="213"/>
        <source>Larger Time Step</source>
        <translation>Увеличить шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="216"/>
        <source>Smaller Time Step</source>
        <translation>Уменьшить шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="223"/>
        <source>Simulation</source>
        <translation>Симуляция</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="230"/>
        <location filename="../ui/main_window.cpp" line="231"/>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="232"/>
        <source>Simulated seconds per real second</source>
        <translation>Секунд модели за секунду реального времени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="240"/>
        <source>Gravity</source>
        <translation>Гравитация</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="243"/>
        <source>Gravity %1</source>
        <translation>Гравитация %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="245"/>
        <source>Gravity %1 (m/s²)</source>
        <translation>Гравитация %1 (m/s²)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="249"/>
        <source>Change Gravity</source>
        <translation>Изменить гравитацию</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="254"/>
        <source>Step</source>
        <translation>Шаг</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="256"/>
        <source>Time step</source>
        <translation>Шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="257"/>
        <source>Time step in seconds (+ and - keys)</source>
        <translation>Шаг по времени в секундах (клавиши + и -)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="261"/>
        <source>Change Time Step</source>
        <translation>Изменить шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="267"/>
        <source>Exact (event-driven), swept, or discrete steps</source>
        <translation>exact (по событиям), swept или discrete (фиксированные шаги)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="269"/>
        <source>Change Method</source>
        <translation>Изменить метод</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="275"/>
        <source>Integrator of the swept and discrete methods</source>
        <translation>Интегратор для методов swept и discrete</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="277"/>
        <source>Change Integrator</source>
        <translation>Изменить интегратор</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="284"/>
        <source>&amp;File</source>
        <translation>&amp;Файл</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="286"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Недавние файлы</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="293"/>
        <source>&amp;Edit</source>
        <translation>&amp;Правка</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="300"/>
        <source>&amp;Simulation</source>
        <translation>&amp;Симуляция</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="303"/>
        <source>Speed vs &amp;Accuracy…</source>
        <translation>Скорость и &amp;точность…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="408"/>
        <source>The edit does not fit the running state (%1): restarted from the edited scene.</source>
        <translation>Правка не согласуется с идущей симуляцией (%1): перезапуск с изменённой сцены.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="453"/>
        <source>Select</source>
        <translation>Выбор</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="454"/>
        <source>Add Ball</source>
        <translation>Добавить шар</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="455"/>
        <source>Add Plane</source>
        <translation>Добавить плоскость</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="456"/>
        <source>Add Cylinder</source>
        <translation>Добавить цилиндр</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="457"/>
        <source>Tools</source>
        <translation>Инструменты</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="464"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="470"/>
        <source>Snap to &amp;Grid</source>
        <translation>Привязка к &amp;сетке</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="473"/>
        <source>Moves land on multiples of %1 m</source>
        <translation>Перемещения кратны %1 m</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="482"/>
        <source>%1[*] — Carom</source>
        <translation>%1[*] — Carom</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="508"/>
        <source>Apply Settings</source>
        <translation>Применить настройки</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="569"/>
        <source>&amp;New</source>
        <translation>&amp;Создать</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="574"/>
        <source>&amp;Open…</source>
        <translation>&amp;Открыть…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="579"/>
        <source>Open Scene</source>
        <translation>Открыть сцену</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="579"/>
        <source>Carom scenes (*.carom *.json);;All files (*)</source>
        <translation>Сцены Carom (*.carom *.json);;Все файлы (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="582"/>
        <source>&amp;Save</source>
        <translation>Со&amp;хранить</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="585"/>
        <source>Save &amp;As…</source>
        <translation>Сохранить &amp;как…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="596"/>
        <source>Cannot Open Scene</source>
        <translation>Не удаётся открыть сцену</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="607"/>
        <source>an unsaved scene</source>
        <translation>несохранённая сцена</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="609"/>
        <source>Recover Scene</source>
        <translation>Восстановление сцены</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="610"/>
        <source>Carom did not close properly while %1 had unsaved changes. The copy saved at %2 can be recovered.</source>
        <translation>Carom завершился некорректно, когда в «%1» были несохранённые изменения. Копию, сохранённую %2, можно восстановить.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="614"/>
        <source>&amp;Recover</source>
        <translation>&amp;Восстановить</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="615"/>
        <source>&amp;Discard</source>
        <translation>&amp;Отбросить</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="616"/>
        <source>Not &amp;Now</source>
        <translation>Не &amp;сейчас</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="623"/>
        <source>Cannot Recover Scene</source>
        <translation>Не удаётся восстановить сцену</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="643"/>
        <source>untitled</source>
        <translation>без имени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="646"/>
        <source>Save Scene</source>
        <translation>Сохранить сцену</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="647"/>
        <source>Carom scenes (*.carom);;All files (*)</source>
        <translation>Сцены Carom (*.carom);;Все файлы (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="658"/>
        <source>Cannot Save Scene</source>
        <translation>Не удаётся сохранить сцену</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="663"/>
        <source>Saved %1</source>
        <translation>Сохранено: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="671"/>
        <source>Unsaved Changes</source>
        <translation>Несохранённые изменения</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="672"/>
        <source>The scene %1 has unsaved changes. Save them?</source>
        <translation>В сцене %1 есть несохранённые изменения. Сохранить их?</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="706"/>
        <source>(none)</source>
        <translation>(нет)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="727"/>
        <source>&amp;Undo</source>
        <translation>&amp;Отменить</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="729"/>
        <source>&amp;Redo</source>
        <translation>&amp;Повторить</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="733"/>
        <source>&amp;Copy</source>
        <translation>&amp;Копировать</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="736"/>
        <source>&amp;Paste</source>
        <translation>В&amp;ставить</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="739"/>
        <source>&amp;Duplicate</source>
        <translation>&amp;Дублировать</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="742"/>
        <source>Duplicate</source>
        <translation>Дублировать</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="744"/>
        <source>De&amp;lete</source>
        <translation>&amp;Удалить</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="747"/>
        <source>Select &amp;All</source>
        <translation>Выделить &amp;всё</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="757"/>
        <source>&amp;Use Current State as Initial</source>
        <translation>&amp;Сделать текущее состояние начальным</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="760"/>
        <source>Edits Apply to the &amp;Running State</source>
        <translation>Правки применяются к &amp;идущей симуляции</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="764"/>
        <source>Off: an edit restarts the simulation from the edited scene. On: balls the edit leaves alone keep their running state.</source>
        <translation>Выключено: правка перезапускает симуляцию с изменённой сцены. Включено: шары, которых правка не касается, сохраняют текущее состояние.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="773"/>
        <source>History</source>
        <translation>История</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="796"/>
        <source>clipboard</source>
        <translation>буфер обмена</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="798"/>
        <source>Nothing to paste: %1</source>
        <translation>Нечего вставить: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="801"/>
        <source>Paste</source>
        <translation>Вставить</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="825"/>
        <source>Cannot place the objects: %1</source>
        <translation>Не удаётся разместить объекты: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="832"/>
        <source>Delete</source>
        <translation>Удалить</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="844"/>
        <source>Use Current State as Initial</source>
        <translation>Сделать текущее состояние начальным</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="291"/>
        <source>&amp;Quit</source>
        <translation>&amp;Выход</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="307"/>
        <source>&amp;Examples</source>
        <translation>&amp;Примеры</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="319"/>
        <source>&amp;View</source>
        <translation>&amp;Вид</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="328"/>
        <source>&amp;Language</source>
        <translation>&amp;Язык</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="338"/>
        <source>The language changes when Carom is next started.</source>
        <translation>Язык изменится при следующем запуске Carom.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="549"/>
        <source>t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %5 balls   E = %6 J (drift %7)</source>
        <translation>t = %1 s   ×%2 от реального времени   %3 fps   столкновений/s: %4   шаров: %5   E = %6 J (дрейф %7)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="559"/>
        <source>   sound unavailable</source>
        <translation>   звук недоступен</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="561"/>
        <source>   muted</source>
        <translation>   звук выключен</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="562"/>
        <source>   — the physics cannot keep up; running slower</source>
        <translation>   — физика не успевает; замедленный ход</translation>
    </message>
</context>
<context>
    <name>carom::ui::NumberBox</name>
    <message>
        <location filename="../ui/number_box.cpp" line="35"/>
        <source>must be finite (got %1)</source>
        <translation>должно быть конечным (получено %1)</translation>
    </message>
    <message>
        <location filename="../ui/number_box.cpp" line="37"/>
        <source>must be between %1 and %2 (got %3)</source>
        <translation>должно быть от %1 до %2 (получено %3)</translation>
    </message>
    <message>
        <location filename="../ui/number_box.cpp" line="76"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>carom::ui::OutlineDock</name>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="143"/>
        <source>Outline</source>
        <translation>Структура</translation>
    </message>
</context>
<context>
    <name>carom::ui::OutlineModel</name>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="97"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/editor/outline_dock.cpp" line="131"/>
        <source>Rename</source>
        <translation>Переименовать</translation>
    </message>
</context>
<context>
    <name>carom::ui::PropertiesDock</name>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="50"/>
        <source>Properties</source>
        <translation>Свойства</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70"/>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70"/>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70"/>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="70"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="71"/>
        <source>(any length)</source>
        <translation>(любой длины)</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="72"/>
        <source>Name</source>
        <translation>Имя</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="72"/>
        <source>Rename</source>
        <translation>Переименовать</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="76"/>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="77"/>
        <source>Choose a colour</source>
        <translation>Выбрать цвет</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="80"/>
        <source>Colour</source>
        <translation>Цвет</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="80"/>
        <source>Change Colour</source>
        <translation>Изменить цвет</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="85"/>
        <location filename="../ui/editor/properties_dock.cpp" line="289"/>
        <source>default</source>
        <translation>по умолчанию</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="88"/>
        <source>Position</source>
        <translation>Положение</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="88"/>
        <location filename="../ui/editor/properties_dock.cpp" line="96"/>
        <source>Move</source>
        <translation>Переместить</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="90"/>
        <source>Velocity</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="90"/>
        <source>Change Velocity</source>
        <translation>Изменить скорость</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="92"/>
        <location filename="../ui/editor/properties_dock.cpp" line="106"/>
        <source>Radius</source>
        <translation>Радиус</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="92"/>
        <location filename="../ui/editor/properties_dock.cpp" line="106"/>
        <source>Change Radius</source>
        <translation>Изменить радиус</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="94"/>
        <source>Mass</source>
        <translation>Масса</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="94"/>
        <source>Change Mass</source>
        <translation>Изменить массу</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="96"/>
        <source>Point</source>
        <translation>Точка</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="101"/>
        <source>Normal</source>
        <translation>Нормаль</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="101"/>
        <source>Turn Plane</source>
        <translation>Повернуть плоскость</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="103"/>
        <source>Axis</source>
        <translation>Ось</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="103"/>
        <source>Turn Cylinder</source>
        <translation>Повернуть цилиндр</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="109"/>
        <source>Gravity</source>
        <translation>Гравитация</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="109"/>
        <source>Change Gravity</source>
        <translation>Изменить гравитацию</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="111"/>
        <source>Time step</source>
        <translation>Шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="111"/>
        <source>Change Time Step</source>
        <translation>Изменить шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="113"/>
        <location filename="../ui/editor/properties_dock.cpp" line="212"/>
        <source>Restitution</source>
        <translation>Восстановление</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="113"/>
        <location filename="../ui/editor/properties_dock.cpp" line="212"/>
        <source>Change Restitution</source>
        <translation>Изменить коэффициент восстановления</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="211"/>
        <source>0 to 1; empty: the world&apos;s restitution</source>
        <translation>От 0 до 1; пусто — коэффициент мира</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="115"/>
        <source>Method</source>
        <translation>Метод</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="115"/>
        <source>Change Method</source>
        <translation>Изменить метод</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="118"/>
        <source>Integrator</source>
        <translation>Интегратор</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="118"/>
        <source>Change Integrator</source>
        <translation>Изменить интегратор</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="247"/>
        <source>World (nothing selected)</source>
        <translation>Мир (ничего не выбрано)</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="253"/>
        <location filename="../ui/editor/properties_dock.cpp" line="333"/>
        <location filename="../ui/editor/properties_dock.cpp" line="364"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/editor/properties_dock.cpp" line="255"/>
        <source>%1: %n selected</source>
        <translation>
            <numerusform>%1: выбран %n</numerusform>
            <numerusform>%1: выбрано %n</numerusform>
            <numerusform>%1: выбрано %n</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/editor/properties_dock.cpp" line="258"/>
        <source>%n objects selected</source>
        <translation>
            <numerusform>Выбран %n объект</numerusform>
            <numerusform>Выбрано %n объекта</numerusform>
            <numerusform>Выбрано %n объектов</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="267"/>
        <source>mixed</source>
        <translation>разные</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="302"/>
        <source>world&apos;s (%1)</source>
        <translation>как у мира (%1)</translation>
    </message>
    <message>
        <location filename="../ui/editor/properties_dock.cpp" line="379"/>
        <source>Object Colour</source>
        <translation>Цвет объекта</translation>
    </message>
</context>
<context>
    <name>carom::ui::SceneDocument</name>
    <message>
        <location filename="../ui/editor/scene_document.cpp" line="55"/>
        <source>untitled</source>
        <translation>без имени</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/carom_main.cpp" line="23"/>
        <source>Collision physics sandbox</source>
        <translation>Песочница для физики столкновений</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="26"/>
        <source>Scene file to open</source>
        <translation>Файл сцены для открытия</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="29"/>
        <source>Save a picture of the window and quit.</source>
        <translation>Сохранить снимок окна и выйти.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="30"/>
        <source>file.png</source>
        <translation>файл.png</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="33"/>
        <source>Run the simulation this long before --screenshot.</source>
        <translation>Сколько секунд выполнять симуляцию перед --screenshot.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="34"/>
        <source>seconds</source>
        <translation>секунды</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="36"/>
        <source>Language of the program (en, ru, de).</source>
        <translation>Язык программы (en, ru, de).</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="37"/>
        <source>code</source>
        <translation>код</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="40"/>
        <source>Run a gas of N balls for 5 s with the view at 1280x720, print frame times and the longest GUI stall, and quit.</source>
        <translation>Запустить газ из N шаров на 5 с при виде 1280x720, вывести время кадров и самую долгую задержку интерфейса и выйти.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="46"/>
        <source>Run a gas at about 10,000 collisions a second with explosions and sound for S seconds, print the collision rate, frame rate, GUI stalls and memory every 10 s, and quit.</source>
        <translation>Запустить газ примерно с 10 000 столкновений в секунду со взрывами и звуком на S секунд, каждые 10 с выводить частоту столкновений, частоту кадров, задержки GUI и память, затем выйти.</translation>
    </message>
</context>
</TS>
